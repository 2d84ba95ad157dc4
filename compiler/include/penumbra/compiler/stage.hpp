// The build pipeline's unit of work (ShaderJob) and the uniform interface of
// its stages: preprocess, compile, validate, optimize, cross-compile,
// reflect, write. Each stage reads what earlier stages filled in and adds
// its own product, like a SPIRV-Tools Pass.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/compiler/model.hpp"
#include "penumbra/compiler/reflection.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// A pass of the shadow pipeline; each is a vertex + fragment pair.
enum class PassKind { depth, query };
std::string_view to_string(PassKind pass);
std::string_view to_string(ShaderStage stage);

// One shader stage of one pass, for one target, of one variant (or shared by
// every variant when `variant` is null).
struct ShaderJob {
  // Inputs.
  const Variant* variant = nullptr;  // null: the shader does not depend on the variant
  Target target = Target::spirv;
  PassKind pass = PassKind::query;
  ShaderStage stage = ShaderStage::fragment;
  std::string source_path;  // in shaderlib/, e.g. "passes/query.frag"

  // Products, in pipeline order.
  std::string preprocessed;          // preprocess: GLSL with includes and defines resolved
  std::vector<std::uint32_t> spirv;  // compile (then optimize): SPIR-V 1.0
  std::string text;                  // cross-compile: target source (empty for spirv)
  ShaderInterface interface;         // reflect
  std::string output_path;           // write: file path relative to the output directory

  // "variant pcss_b16_p16_whitepaper16, target hlsl_dx9, query.frag" for messages.
  std::string describe() const;
};

class Stage {
 public:
  virtual ~Stage() = default;
  virtual std::string_view name() const = 0;
  virtual Status process(ShaderJob& job) const = 0;
};

}  // namespace penumbra
