#include "sampler_units.hpp"

namespace penumbra::gl {
namespace {

// GLSL 4.20 introduced layout(binding) on samplers and uniform blocks.
constexpr int kFirstVersionWithBindings = 420;

GLint interface_binding(const std::string& name) {
  if (name == "shadow_depth") return 1;
  if (name == "shadow_cmp") return 2;
  return 3;  // receivers
}

Error unit_error(std::string message) {
  return make_error(Error::Kind::bad_input, "query pass", std::move(message));
}

}  // namespace

Result<std::vector<SamplerUnit>> assign_sampler_units(GLuint program, const ProgramInterface& iface,
                                                      int glsl_version) {
  GLint unit_count = 0;
  glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &unit_count);
  std::vector<SamplerUnit> units;
  for (const SamplerUniform& sampler : iface.samplers) {
    GLint unit = 0;
    if (glsl_version >= kFirstVersionWithBindings) {
      glGetUniformiv(program, sampler.location, &unit);
    } else {
      unit = interface_binding(sampler.name);
      glProgramUniform1i(program, sampler.location, unit);
    }
    if (unit < 0 || unit >= unit_count) {
      return unit_error("sampler '" + sampler.name + "' uses texture unit " + std::to_string(unit) +
                        "; GL has units 0 to " + std::to_string(unit_count - 1));
    }
    for (const SamplerUnit& other : units) {
      if (other.unit == static_cast<GLuint>(unit)) {
        return unit_error("samplers '" + other.name + "' and '" + sampler.name +
                          "' both use texture unit " + std::to_string(unit) +
                          "; give each its own layout(binding = N)");
      }
    }
    units.push_back({sampler.name, static_cast<GLuint>(unit)});
  }
  return units;
}

}  // namespace penumbra::gl
