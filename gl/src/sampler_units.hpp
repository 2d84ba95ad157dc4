// Which texture unit each of a program's samplers reads.
#pragma once

#include <string>
#include <vector>

#include "gl_api.hpp"
#include "pass_role.hpp"
#include "penumbra/support/result.hpp"
#include "program_interface.hpp"

namespace penumbra::gl {

struct SamplerUnit {
  std::string name;  // one of kImageSlots' names
  GLuint unit = 0;
};

// GLSL 4.20 and later declare the units (layout(binding = N)); GL reports
// them through glGetUniformiv and they are kept, as a GL 4.5 engine does.
// Earlier versions cannot declare them: each sampler is set by name to the
// binding docs/shader-interface.md gives it (kImageSlots: shadow_depth 1,
// shadow_cmp 2, receivers 3, shadow_minmax 4, minmax_source 5). Errors
// (bad_input, `where` = role.where): two samplers on one unit (they need
// different textures or sampler objects), or a unit GL does not have.
Result<std::vector<SamplerUnit>> assign_sampler_units(GLuint program, const ProgramInterface& iface,
                                                      int glsl_version, const PassRole& role);

}  // namespace penumbra::gl
