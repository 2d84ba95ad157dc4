// Translating a stage's Direct3D bytecode (the .d3dbc/.dxbc files beside the
// hlsl_* text) to Vulkan SPIR-V with vkd3d-compiler, as Proton's vkd3d does
// when a Direct3D engine loads it (docs/verification.md).
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

#include "penumbra/compiler/text_frontend.hpp"
#include "penumbra/model/model.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

class Vkd3dMemo;

struct BytecodeTranslator {
  std::filesystem::path compiler;             // vkd3d-compiler 2.1 or newer
  std::chrono::milliseconds timeout{60'000};  // per file
  std::shared_ptr<Vkd3dMemo> memo = nullptr;  // shares identical runs; none: each call runs it
};

// vkd3d-compiler's successful results by what it read, for the translators
// that share it: its output depends on its input alone, and one verify asks
// for the same many times (every variant's runs load their target's depth
// pass; the bytecode path and the Wine runtimes compile the same engine
// shaders). Failures are not kept, so each error names its own file. Safe
// from any thread.
class Vkd3dMemo {
 public:
  // What an earlier success with the same key made, if any.
  std::optional<std::string> find_bytecode(const std::string& key) const;
  std::optional<FrontEndResult> find_spirv(const std::string& key) const;
  void add_bytecode(std::string key, std::string bytecode);
  void add_spirv(std::string key, FrontEndResult spirv);

 private:
  mutable std::mutex mutex_;
  std::unordered_map<std::string, std::string> bytecode_;
  std::unordered_map<std::string, FrontEndResult> spirv_;
};

// `bytecode`, `target`'s bytecode of `stage` (bytecode_format()), as
// SPIR-V that passes spirv-val for Vulkan 1.0: resources named by register
// (t#, s#, cb#_#), bindings in vkd3d's declaration order, in a descriptor
// set per stage (the vertex stage's 0, the fragment stage's 1: Direct3D's
// register files are per stage). Errors (compile, at the file) name the translator's
// message; bad_input for a target without bytecode.
Result<FrontEndResult> translate_bytecode(const BytecodeTranslator& translator, Target target,
                                          ShaderStage stage, const std::filesystem::path& bytecode);

// `text`, HLSL for `target`'s `stage` with entry point main, compiled by
// the translator's vkd3d-compiler to the target's bytecode (bytecode_format())
// in `output`: what a Direct3D engine's build does with its own shaders.
// `name` names the source in errors (compile: the compiler's message);
// bad_input for a target without bytecode.
Status compile_hlsl_bytecode(const BytecodeTranslator& translator, Target target, ShaderStage stage,
                             const std::string& text, const std::string& name,
                             const std::filesystem::path& output);

// The same, then translated
// to SPIR-V as translate_bytecode() does: the way a Direct3D engine's own
// shaders reach a Vulkan driver under Proton.
Result<FrontEndResult> compile_hlsl_to_spirv(const BytecodeTranslator& translator, Target target,
                                             ShaderStage stage, const std::string& text,
                                             const std::string& name);

}  // namespace penumbra
