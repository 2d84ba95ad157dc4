#include <memory>
#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_hlsl.hpp>

#include "penumbra/compiler/targets.hpp"
#include "stages/stages.hpp"
#include "targets/dx10_comparison_textures.hpp"
#include "targets/dx9_half_pixel.hpp"
#include "targets/dx9_registers.hpp"
#include "targets/rules.hpp"

namespace penumbra {
namespace {

using spirv_cross::CompilerGLSL;
using spirv_cross::CompilerHLSL;

std::unique_ptr<CompilerGLSL> make_glsl(const ShaderJob& job) {
  auto compiler = std::make_unique<CompilerGLSL>(job.spirv);
  CompilerGLSL::Options options;
  options.vertex.fixup_clipspace = true;  // Vulkan z in [0, 1] to GL's [-1, 1]
  options.fragment.default_float_precision = CompilerGLSL::Options::Highp;
  options.fragment.default_int_precision = CompilerGLSL::Options::Highp;
  switch (job.target) {
    case Target::glsl450:
      options.version = 450;  // keeps explicit bindings and locations
      break;
    case Target::glsl330:
      options.version = 330;
      options.enable_420pack_extension = false;              // no binding qualifiers in 3.30
      options.emit_uniform_buffer_as_plain_uniforms = true;  // uniforms set by name
      break;
    default:  // essl300
      options.version = 300;
      options.es = true;
      break;
  }
  compiler->set_common_options(options);
  return compiler;
}

std::unique_ptr<CompilerHLSL> make_hlsl(const ShaderJob& job) {
  auto compiler = std::make_unique<CompilerHLSL>(job.spirv);
  CompilerGLSL::Options common;
  common.vertex.flip_vert_y = true;  // keeps row j = 0 first under D3D's viewport
  compiler->set_common_options(common);
  CompilerHLSL::Options options;
  options.shader_model = traits(job.target).shader_model * 10;  // SPIRV-Cross's 30, 40, ...
  compiler->set_hlsl_options(options);
  return compiler;
}

}  // namespace

Status CrossCompileStage::process(ShaderJob& job) const {
  PENUMBRA_TRY(check_target_rules(job));
  if (job.target == Target::spirv) return {};
  try {
    if (traits(job.target).is_hlsl) {
      job.text = make_hlsl(job)->compile();
    } else {
      job.text = make_glsl(job)->compile();
    }
  } catch (const spirv_cross::CompilerError& error) {
    return make_error(Error::Kind::compile, job.describe(),
                      std::string("cannot express this for ") + std::string(to_string(job.target)) +
                          ": " + error.what());
  }
  const std::string_view prefix = job.form == ShaderForm::function ? kFunctionPrefix : "";
  if (traits(job.target).shader_model >= 4) {
    job.text = dx10_comparison_textures_as_scalar(job.text, prefix);
  }
  if (job.target == Target::hlsl_dx9) {
    auto rewritten = dx9_explicit_registers(job.text, prefix);
    if (rewritten) rewritten = dx9_half_pixel_after_flip(*rewritten);
    if (!rewritten)
      return make_error(Error::Kind::compile, job.describe(), rewritten.error().message);
    job.text = std::move(*rewritten);
  }
  return {};
}

}  // namespace penumbra
