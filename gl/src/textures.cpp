#include "textures.hpp"

#include <string>
#include <vector>

#include "gl_check.hpp"
#include "penumbra/support/image_checks.hpp"

namespace penumbra::gl {
namespace {

Error input_error(const char* where, std::string message) {
  return make_error(Error::Kind::bad_input, where, std::move(message));
}

Status check_size(const char* where, const FloatImage& image) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (image.width < 1 || image.height < 1 || image.width > max_size || image.height > max_size) {
    return input_error(where, std::to_string(image.width) + "x" + std::to_string(image.height) +
                                  ": each side must be 1 to " + std::to_string(max_size) +
                                  " (GL_MAX_TEXTURE_SIZE)");
  }
  return {};
}

// A width x height texture of one level, filled from `data` (rows of floats
// in `format`, row 0 first) unless it is null.
Result<Texture> create_texture(GLenum internal_format, int width, int height, GLenum format,
                               const float* data, const char* what) {
  Texture texture = create_texture_2d();
  glTextureStorage2D(texture.get(), 1, internal_format, width, height);
  if (data != nullptr) {
    glTextureSubImage2D(texture.get(), 0, 0, 0, width, height, format, GL_FLOAT, data);
  }
  PENUMBRA_TRY(check_gl(what));
  return texture;
}

}  // namespace

Status check_query_inputs(const FloatImage& normalized_depth, const FloatImage& receivers) {
  PENUMBRA_TRY(check_normalized_depth(normalized_depth));
  PENUMBRA_TRY(check_receivers(receivers));
  PENUMBRA_TRY(check_size("shadow map", normalized_depth));
  PENUMBRA_TRY(check_size("receivers", receivers));
  return {};
}

Result<Texture> upload_depth(const FloatImage& normalized_depth) {
  return create_texture(GL_DEPTH_COMPONENT32F, normalized_depth.width, normalized_depth.height,
                        GL_DEPTH_COMPONENT, normalized_depth.data.data(),
                        "uploading the shadow map (GL_DEPTH_COMPONENT32F)");
}

Result<Texture> upload_receivers(const FloatImage& receivers) {
  const std::vector<float> rgba = receivers_to_rgba(receivers);
  return create_texture(GL_RGBA32F, receivers.width, receivers.height, GL_RGBA, rgba.data(),
                        "uploading the receivers (GL_RGBA32F)");
}

Result<Texture> create_visibility_target(int width, int height) {
  return create_texture(GL_R32F, width, height, GL_RED, nullptr,
                        "creating the visibility target (GL_R32F)");
}

}  // namespace penumbra::gl
