#include "pass_program.hpp"

#include <algorithm>

#include "gl_check.hpp"
#include "gl_program.hpp"
#include "sampler_objects.hpp"

namespace penumbra::gl {

bool PassProgram::reads(TextureId texture) const {
  return std::any_of(bindings.textures.begin(), bindings.textures.end(),
                     [&](const TextureSlot& slot) { return slot.texture == texture; });
}

Result<PassProgram> prepare_pass(const GlPass& pass, PassKind kind) {
  return prepare_program(pass, std::string(to_string(kind)) + " pass", 2);
}

Result<PassProgram> prepare_program(const GlPass& pass, std::string where,
                                    std::uint32_t position_components) {
  PassProgram prepared;
  prepared.where = std::move(where);
  prepared.reflection = &pass.reflection;
  auto program =
      build_program(pass.vert, pass.frag, pass.reflection, prepared.where, position_components);
  if (!program) return program.error();
  prepared.program = std::move(*program);
  // build_program admitted one render target.
  const RenderTarget& target = pass.reflection.render_targets.front();
  auto format = texel_format(target.format, prepared.where, "render target '" + target.name + "'");
  if (!format) return format.error();
  prepared.target_format = *format;
  auto bindings = bind_by_reflection(prepared.program.get(), pass.reflection, prepared.where);
  if (!bindings) return bindings.error();
  prepared.bindings = std::move(*bindings);
  for (const TextureSlot& slot : prepared.bindings.textures) {
    auto sampler = create_sampler_object(slot.binding->sampler.state);
    if (!sampler) return sampler.error();
    prepared.samplers.push_back(std::move(*sampler));
  }
  PENUMBRA_TRY(check_gl("preparing the " + prepared.where));
  return prepared;
}

}  // namespace penumbra::gl
