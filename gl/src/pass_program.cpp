#include "pass_program.hpp"

#include <algorithm>
#include <string>

#include "gl_check.hpp"
#include "gl_program.hpp"

namespace penumbra::gl {

bool PassProgram::reads(std::string_view name) const {
  return std::any_of(units.begin(), units.end(),
                     [&](const SamplerUnit& unit) { return unit.name == name; });
}

Result<PassProgram> prepare_pass(std::string_view vertex_text, std::string_view fragment_text,
                                 const PassRole& role) {
  PassProgram pass;
  pass.role = &role;
  auto program = build_program(vertex_text, fragment_text, role);
  if (!program) return program.error();
  pass.program = std::move(*program);
  auto iface = reflect_program(pass.program.get(), role);
  if (!iface) return iface.error();
  pass.iface = std::move(*iface);
  // The fragment text's #version decides whether the shader declares units.
  auto units =
      assign_sampler_units(pass.program.get(), pass.iface, glsl_version(fragment_text), role);
  if (!units) return units.error();
  pass.units = std::move(*units);
  PENUMBRA_TRY(check_gl("preparing the " + std::string(role.where)));
  return pass;
}

}  // namespace penumbra::gl
