// A pass's program, ready to draw: compiled, linked, its interface reflected
// and its samplers given units.
#pragma once

#include <string_view>
#include <vector>

#include "gl_names.hpp"
#include "pass_role.hpp"
#include "penumbra/support/result.hpp"
#include "program_interface.hpp"
#include "sampler_units.hpp"

namespace penumbra::gl {

struct PassProgram {
  const PassRole* role = nullptr;
  Program program;
  ProgramInterface iface;
  std::vector<SamplerUnit> units;

  // Whether the fragment stage reads the image `name` (a kImageSlots name).
  bool reads(std::string_view name) const;
};

// Errors: those of build_program, reflect_program and assign_sampler_units,
// all with `where` = role.where; device for a GL error.
Result<PassProgram> prepare_pass(std::string_view vertex_text, std::string_view fragment_text,
                                 const PassRole& role);

}  // namespace penumbra::gl
