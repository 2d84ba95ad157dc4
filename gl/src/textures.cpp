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
                               const float* data, const std::string& what) {
  Texture texture = create_texture_2d();
  glTextureStorage2D(texture.get(), 1, internal_format, width, height);
  if (data != nullptr) {
    glTextureSubImage2D(texture.get(), 0, 0, 0, width, height, format, GL_FLOAT, data);
  }
  PENUMBRA_TRY(check_gl(what));
  return texture;
}

}  // namespace

Status check_shadow_map(const FloatImage& normalized_depth) {
  PENUMBRA_TRY(check_normalized_depth(normalized_depth));
  return check_size("shadow map", normalized_depth);
}

Status check_query_inputs(const FloatImage& normalized_depth, const FloatImage& receivers) {
  PENUMBRA_TRY(check_shadow_map(normalized_depth));
  PENUMBRA_TRY(check_receivers(receivers));
  return check_size("receivers", receivers);
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

Result<Texture> create_rg_target(int width, int height, const std::string& what) {
  return create_texture(GL_RG32F, width, height, GL_RG, nullptr,
                        "creating " + what + " (GL_RG32F)");
}

Result<Texture> create_rg_chain(int side, int levels, const std::string& what) {
  Texture texture = create_texture_2d();
  glTextureStorage2D(texture.get(), levels, GL_RG32F, side, side);
  // Immutable storage already limits sampling to these levels; said here too.
  glTextureParameteri(texture.get(), GL_TEXTURE_MAX_LEVEL, levels - 1);
  const float far[2] = {1.0f, 1.0f};
  for (int level = 0; level < levels; ++level) {
    glClearTexImage(texture.get(), level, GL_RG, GL_FLOAT, far);
  }
  PENUMBRA_TRY(check_gl("creating " + what + " (GL_RG32F, " + std::to_string(levels) + " levels)"));
  return texture;
}

Result<FloatImage> read_rg(const Texture& texture, int level, int width, int height,
                           const std::string& what) {
  FloatImage image(width, height, 2);
  glGetTextureSubImage(texture.get(), level, 0, 0, 0, width, height, 1, GL_RG, GL_FLOAT,
                       static_cast<GLsizei>(image.data.size() * sizeof(float)), image.data.data());
  PENUMBRA_TRY(check_gl("reading back " + what));
  return image;
}

}  // namespace penumbra::gl
