#include "sampler_objects.hpp"

#include "gl_check.hpp"

namespace penumbra::gl {
namespace {

GLuint create_sampler(GLint min_filter, GLint mag_filter) {
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, min_filter);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, mag_filter);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return sampler;
}

}  // namespace

Result<SamplerObjects> create_sampler_objects() {
  SamplerObjects samplers;
  // A non-mipmap minification filter: the single-level textures are complete.
  samplers.point = create_sampler(GL_NEAREST, GL_NEAREST);
  glSamplerParameteri(samplers.point, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  samplers.compare = create_sampler(GL_LINEAR, GL_LINEAR);
  glSamplerParameteri(samplers.compare, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(samplers.compare, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  // shadow_minmax is read with textureLod at LOD l - 1 = 0 .. N - 1: an exact
  // integer LOD selects that level (LOD 0 magnifies, from the base level),
  // and the LOD range stays GL's default upper bound, not clamped to 0.
  samplers.mip = create_sampler(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  glSamplerParameteri(samplers.mip, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glSamplerParameterf(samplers.mip, GL_TEXTURE_MIN_LOD, 0.0f);
  PENUMBRA_TRY(check_gl("creating the sampler objects"));
  return samplers;
}

}  // namespace penumbra::gl
