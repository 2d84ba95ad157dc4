// A pass's program, ready to draw: compiled, linked and bound by its
// reflection, with a sampler object per texture it samples.
#pragma once

#include <string>
#include <vector>

#include "gl_names.hpp"
#include "penumbra/gl/engine.hpp"
#include "penumbra/model/pass.hpp"
#include "penumbra/support/result.hpp"
#include "reflected_bindings.hpp"
#include "texel_formats.hpp"

namespace penumbra::gl {

struct PassProgram {
  std::string where;  // "query pass": Error::where of everything the pass reports
  const PassReflection* reflection = nullptr;
  Program program;
  PassBindings bindings;
  std::vector<Sampler> samplers;               // bindings.textures[i] samples through samplers[i]
  const TexelFormat* target_format = nullptr;  // of its one render target

  // Whether the program samples `texture`.
  bool reads(TextureId texture) const;
};

// `pass` as the `kind` pass, drawn over the full-screen triangle. Errors:
// those of build_program and bind_by_reflection, all with `where` = "<kind>
// pass"; device for a GL error.
Result<PassProgram> prepare_pass(const GlPass& pass, PassKind kind);

// `program`, whose vertex input takes `position_components` floats, as
// `where`. Errors as prepare_pass's.
Result<PassProgram> prepare_program(const GlPass& program, std::string where,
                                    std::uint32_t position_components);

}  // namespace penumbra::gl
