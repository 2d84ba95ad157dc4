#include "penumbra/model/target_traits.hpp"

#include <cstddef>

namespace penumbra {
namespace {

using enum ReflectionDialect;

// Indexed by the enum values, so the order must follow Target's declaration.
constexpr TargetTraits kTraits[] = {
    {.name = "spirv", .dialect = spirv, .is_text = false},
    {.name = "glsl450", .dialect = glsl450},
    {.name = "glsl330", .dialect = glsl330},
    {.name = "essl300", .dialect = essl300},
    // Direct3D 11 binds as Direct3D 10: cbuffer b#, Texture2D t#, samplers s#.
    {.name = "hlsl_dx11",
     .dialect = d3d10,
     .is_hlsl = true,
     .shader_model = 5,
     .rolled_sample_loops = true},
    {.name = "hlsl_dx10",
     .dialect = d3d10,
     .is_hlsl = true,
     .shader_model = 4,
     .rolled_sample_loops = true},
    // SM 3.0 has no comparison sampler: compares are made in the shader.
    {.name = "hlsl_dx9",
     .dialect = d3d9,
     .comparison_sampler = false,
     .is_hlsl = true,
     .shader_model = 3,
     .disk_textures = true,
     .rolled_sample_loops = true,
     .walk_step_limit = 224,
     .integer_ops = false,
     .texture_arrays = false},
};
static_assert(std::size(kTraits) == kAllTargets.size());

}  // namespace

TargetTraits traits(Target target) {
  return kTraits[static_cast<std::size_t>(target)];
}

}  // namespace penumbra
