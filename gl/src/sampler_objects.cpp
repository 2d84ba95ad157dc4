#include "sampler_objects.hpp"

#include "gl_check.hpp"

namespace penumbra::gl {
namespace {

GLuint create_sampler(GLint filter) {
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  // A non-mipmap minification filter: the single-level textures are complete.
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, filter);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, filter);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return sampler;
}

}  // namespace

Result<SamplerObjects> create_sampler_objects() {
  SamplerObjects samplers;
  samplers.point = create_sampler(GL_NEAREST);
  glSamplerParameteri(samplers.point, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  samplers.compare = create_sampler(GL_LINEAR);
  glSamplerParameteri(samplers.compare, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(samplers.compare, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  PENUMBRA_TRY(check_gl("creating the sampler objects"));
  return samplers;
}

}  // namespace penumbra::gl
