#include "sampler_units.hpp"

namespace penumbra::gl {
namespace {

// GLSL 4.20 introduced layout(binding) on samplers and uniform blocks.
constexpr int kFirstVersionWithBindings = 420;

Error unit_error(const PassRole& role, std::string message) {
  return make_error(Error::Kind::bad_input, std::string(role.where), std::move(message));
}

}  // namespace

Result<std::vector<SamplerUnit>> assign_sampler_units(GLuint program, const ProgramInterface& iface,
                                                      int glsl_version, const PassRole& role) {
  GLint unit_count = 0;
  glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &unit_count);
  std::vector<SamplerUnit> units;
  for (const SamplerUniform& sampler : iface.samplers) {
    GLint unit = 0;
    if (glsl_version >= kFirstVersionWithBindings) {
      glGetUniformiv(program, sampler.location, &unit);
    } else {
      // reflect_program admitted only names of kImageSlots.
      unit = find_image_slot(sampler.name)->binding;
      glProgramUniform1i(program, sampler.location, unit);
    }
    if (unit < 0 || unit >= unit_count) {
      return unit_error(role, "sampler '" + sampler.name + "' uses texture unit " +
                                  std::to_string(unit) + "; GL has units 0 to " +
                                  std::to_string(unit_count - 1));
    }
    for (const SamplerUnit& other : units) {
      if (other.unit == static_cast<GLuint>(unit)) {
        return unit_error(role, "samplers '" + other.name + "' and '" + sampler.name +
                                    "' both use texture unit " + std::to_string(unit) +
                                    "; give each its own layout(binding = N)");
      }
    }
    units.push_back({sampler.name, static_cast<GLuint>(unit)});
  }
  return units;
}

}  // namespace penumbra::gl
