#include "sampler_objects.hpp"

#include "gl_check.hpp"

namespace penumbra::gl {

Result<Sampler> create_sampler_object(const SamplerState& state) {
  Sampler sampler = create_sampler();
  const bool linear = state.filter == Filter::linear;
  const GLint filter = linear ? GL_LINEAR : GL_NEAREST;
  GLint min_filter = filter;
  if (state.mip_filter == MipFilter::nearest) {
    min_filter = linear ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
    // textureLod(t, uv, l) reads level l exactly: LOD 0 magnifies from the
    // base level, and the upper LOD bound stays GL's default.
    glSamplerParameterf(sampler.get(), GL_TEXTURE_MIN_LOD, 0.0f);
  }
  // Without a mip filter, single-level textures are complete.
  glSamplerParameteri(sampler.get(), GL_TEXTURE_MIN_FILTER, min_filter);
  glSamplerParameteri(sampler.get(), GL_TEXTURE_MAG_FILTER, filter);
  glSamplerParameteri(sampler.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler.get(), GL_TEXTURE_COMPARE_MODE,
                      state.comparison ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
  if (state.comparison) {
    glSamplerParameteri(sampler.get(), GL_TEXTURE_COMPARE_FUNC,
                        state.greater_equal ? GL_GEQUAL : GL_LEQUAL);
  }
  PENUMBRA_TRY(check_gl("creating a sampler object"));
  return sampler;
}

}  // namespace penumbra::gl
