#include <string>

#include "penumbra/compiler/bytecode_frontend.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/support/file.hpp"
#include "penumbra/support/scratch_file.hpp"
#include "spirv/descriptor_sets.hpp"
#include "spirv/validation.hpp"
#include "vkd3d/run_vkd3d.hpp"

namespace penumbra {
namespace {

// Direct3D gives each stage register files of its own; vkd3d-compiler's
// command line takes no binding map, so each stage's descriptors, all in set
// 0 from binding 0, move to a set of their own.
std::uint32_t descriptor_set(ShaderStage stage) {
  return stage == ShaderStage::vertex ? 0 : 1;
}

// A Vkd3dMemo key: what vkd3d-compiler reads for one stage of `target`.
std::string memo_key(Target target, ShaderStage stage, std::string_view input) {
  std::string key(to_string(target));
  key += stage == ShaderStage::vertex ? " vertex\n" : " fragment\n";
  key += input;
  return key;
}

Result<FrontEndResult> run_translation(const BytecodeTranslator& translator,
                                       const BytecodeFormat& format, ShaderStage stage,
                                       const std::filesystem::path& bytecode) {
  const std::string front_end = "vkd3d-compiler " + std::string(format.vkd3d_type) + " to SPIR-V";
  // vkd3d-compiler writes the module to a file: its stdout would interleave
  // the binary with its messages.
  const ScratchFile output("vkd3d", ".spv");
  auto run = run_vkd3d(translator.compiler,
                       {"-x", std::string(format.vkd3d_type), "-b", "spirv-binary", "-o",
                        output.path().string(), bytecode.string()},
                       translator.timeout);
  if (!run) return run.error();
  if (run->timed_out || run->exit_code != 0) {
    const std::string why = run->timed_out ? "no SPIR-V within the time limit"
                                           : "exit status " + std::to_string(run->exit_code);
    return make_error(Error::Kind::compile, bytecode.string(),
                      front_end + ": " + why + (run->output.empty() ? "" : ":\n" + run->output));
  }
  auto spirv = read_spirv_file(output.path());
  if (!spirv) {
    return make_error(Error::Kind::compile, bytecode.string(),
                      front_end + " wrote no SPIR-V: " + spirv.error().message);
  }
  move_to_descriptor_set(*spirv, descriptor_set(stage));
  if (auto valid = validate_vulkan_spirv(*spirv); !valid) {
    return make_error(Error::Kind::compile, bytecode.string(),
                      front_end + " wrote SPIR-V that fails validation:\n" + valid.error().message);
  }
  return FrontEndResult{std::move(*spirv), front_end, {}};
}

Status run_compile(const BytecodeTranslator& translator, const BytecodeFormat& format,
                   const std::string& text, const std::string& name,
                   const std::filesystem::path& output) {
  const ScratchFile source("vkd3d", ".hlsl");
  PENUMBRA_TRY(write_file(source.path(), text));
  auto run = run_vkd3d(translator.compiler,
                       {"-x", "hlsl", "-p", format.profile, "-b", std::string(format.vkd3d_type),
                        "-e", "main", "-o", output.string(), source.path().string()},
                       translator.timeout);
  if (!run) return run.error();
  if (run->timed_out || run->exit_code != 0) {
    const std::string why = run->timed_out ? "no bytecode within the time limit"
                                           : "exit status " + std::to_string(run->exit_code);
    return make_error(Error::Kind::compile, name,
                      "vkd3d-compiler " + format.profile + ": " + why +
                          (run->output.empty() ? "" : ":\n" + run->output));
  }
  return {};
}

}  // namespace

Result<FrontEndResult> translate_bytecode(const BytecodeTranslator& translator, Target target,
                                          ShaderStage stage,
                                          const std::filesystem::path& bytecode) {
  const auto format = bytecode_format(target, stage);
  if (!format) {
    return make_error(Error::Kind::bad_input, bytecode.string(),
                      "target " + std::string(to_string(target)) + " has no Direct3D bytecode");
  }
  std::string key;  // none: not memoized, or a file vkd3d-compiler is left to report
  if (translator.memo) {
    if (auto bytes = read_file(bytecode)) key = memo_key(target, stage, *bytes);
  }
  if (!key.empty()) {
    if (auto known = translator.memo->find_spirv(key)) return *known;
  }
  auto translated = run_translation(translator, *format, stage, bytecode);
  if (translated && !key.empty()) translator.memo->add_spirv(std::move(key), *translated);
  return translated;
}

Status compile_hlsl_bytecode(const BytecodeTranslator& translator, Target target, ShaderStage stage,
                             const std::string& text, const std::string& name,
                             const std::filesystem::path& output) {
  const auto format = bytecode_format(target, stage);
  if (!format) {
    return make_error(Error::Kind::bad_input, name,
                      "target " + std::string(to_string(target)) + " has no Direct3D bytecode");
  }
  if (!translator.memo) return run_compile(translator, *format, text, name, output);
  std::string key = memo_key(target, stage, text);
  if (auto known = translator.memo->find_bytecode(key)) return write_file(output, *known);
  PENUMBRA_TRY(run_compile(translator, *format, text, name, output));
  PENUMBRA_TRY_ASSIGN(std::string bytecode, read_file(output));
  translator.memo->add_bytecode(std::move(key), std::move(bytecode));
  return {};
}

Result<FrontEndResult> compile_hlsl_to_spirv(const BytecodeTranslator& translator, Target target,
                                             ShaderStage stage, const std::string& text,
                                             const std::string& name) {
  const auto format = bytecode_format(target, stage);
  if (!format) {
    return make_error(Error::Kind::bad_input, name,
                      "target " + std::string(to_string(target)) + " has no Direct3D bytecode");
  }
  const ScratchFile bytecode("vkd3d", format->extension);
  PENUMBRA_TRY(compile_hlsl_bytecode(translator, target, stage, text, name, bytecode.path()));
  PENUMBRA_TRY_ASSIGN(FrontEndResult translated,
                      translate_bytecode(translator, target, stage, bytecode.path()));
  translated.front_end = "vkd3d-compiler hlsl to " + std::string(format->vkd3d_type) + " (" +
                         format->profile + "), then " + translated.front_end;
  return translated;
}

}  // namespace penumbra
