#include "textures.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "gl_check.hpp"

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
  if (normalized_depth.channels != 1) {
    return input_error("shadow map", "expected one channel of normalized depth, got " +
                                         std::to_string(normalized_depth.channels));
  }
  if (receivers.channels != 3 && receivers.channels != 4) {
    return input_error("receivers", "expected 3 or 4 channels (u, v, z_r), got " +
                                        std::to_string(receivers.channels));
  }
  PENUMBRA_TRY(check_size("shadow map", normalized_depth));
  PENUMBRA_TRY(check_size("receivers", receivers));
  for (int j = 0; j < normalized_depth.height; ++j) {
    for (int i = 0; i < normalized_depth.width; ++i) {
      const float d = normalized_depth.at(i, j);
      if (std::isfinite(d) && d >= 0.0f && d <= 1.0f) continue;
      return input_error("shadow map", "texel (" + std::to_string(i) + ", " + std::to_string(j) +
                                           ") holds " + std::to_string(d) +
                                           "; normalized depth must be finite and in [0, 1]");
    }
  }
  return {};
}

Result<Texture> upload_depth(const FloatImage& normalized_depth) {
  return create_texture(GL_DEPTH_COMPONENT32F, normalized_depth.width, normalized_depth.height,
                        GL_DEPTH_COMPONENT, normalized_depth.data.data(),
                        "uploading the shadow map (GL_DEPTH_COMPONENT32F)");
}

Result<Texture> upload_receivers(const FloatImage& receivers) {
  std::vector<float> rgba(receivers.pixel_count() * 4, 0.0f);
  for (std::size_t p = 0; p < receivers.pixel_count(); ++p) {
    for (int c = 0; c < receivers.channels; ++c) {
      rgba[p * 4 + c] = receivers.data[p * receivers.channels + c];
    }
  }
  return create_texture(GL_RGBA32F, receivers.width, receivers.height, GL_RGBA, rgba.data(),
                        "uploading the receivers (GL_RGBA32F)");
}

Result<Texture> create_visibility_target(int width, int height) {
  return create_texture(GL_R32F, width, height, GL_RED, nullptr,
                        "creating the visibility target (GL_R32F)");
}

}  // namespace penumbra::gl
