#include "textures.hpp"

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

// `image`'s texels with `channels` channels each, the missing ones 0.
std::vector<float> padded(const FloatImage& image, int channels) {
  std::vector<float> texels(image.pixel_count() * static_cast<std::size_t>(channels), 0.0f);
  for (std::size_t p = 0; p < image.pixel_count(); ++p) {
    for (int c = 0; c < image.channels; ++c) {
      texels[p * channels + c] = image.data[p * image.channels + c];
    }
  }
  return texels;
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

Status check_scene_colour(const FloatImage& scene_colour, const FloatImage& receivers) {
  if (scene_colour.channels != 4 || scene_colour.data.size() != scene_colour.pixel_count() * 4) {
    return input_error("scene colour",
                       "expected four channels (RGBA) of width * height values, "
                       "got " +
                           std::to_string(scene_colour.channels) + " channel(s)");
  }
  if (scene_colour.width != receivers.width || scene_colour.height != receivers.height) {
    return input_error("scene colour", "is " + std::to_string(scene_colour.width) + "x" +
                                           std::to_string(scene_colour.height) +
                                           " but the screen (receivers) is " +
                                           std::to_string(receivers.width) + "x" +
                                           std::to_string(receivers.height));
  }
  return {};
}

Result<Texture> upload(const FloatImage& image, const TexelFormat& format,
                       const std::string& what) {
  const std::vector<float> texels = padded(image, format.channels);
  if (image.layers > 0) {
    // The layers lie one after another, as glTextureSubImage3D reads them.
    const int height = image.layer_height();
    Texture texture = create_texture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(texture.get(), 1, format.internal_format, image.width, height, image.layers);
    glTextureSubImage3D(texture.get(), 0, 0, 0, 0, image.width, height, image.layers,
                        format.pixel_format, GL_FLOAT, texels.data());
    PENUMBRA_TRY(check_gl("uploading " + what + " (" + std::string(format.name()) + ", " +
                          std::to_string(image.layers) + " layers)"));
    return texture;
  }
  Texture texture = create_texture_2d();
  glTextureStorage2D(texture.get(), 1, format.internal_format, image.width, image.height);
  glTextureSubImage2D(texture.get(), 0, 0, 0, image.width, image.height, format.pixel_format,
                      GL_FLOAT, texels.data());
  PENUMBRA_TRY(check_gl("uploading " + what + " (" + std::string(format.name()) + ")"));
  return texture;
}

Result<Texture> create_target(const TexelFormat& format, int width, int height,
                              const std::string& what) {
  Texture texture = create_texture_2d();
  glTextureStorage2D(texture.get(), 1, format.internal_format, width, height);
  PENUMBRA_TRY(check_gl("creating " + what + " (" + std::string(format.name()) + ")"));
  return texture;
}

Result<Texture> create_chain(const TexelFormat& format, int side, int levels,
                             const std::string& what) {
  Texture texture = create_texture_2d();
  glTextureStorage2D(texture.get(), levels, format.internal_format, side, side);
  // Immutable storage already limits sampling to these levels; said here too.
  glTextureParameteri(texture.get(), GL_TEXTURE_MAX_LEVEL, levels - 1);
  const float far[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  for (int level = 0; level < levels; ++level) {
    glClearTexImage(texture.get(), level, format.pixel_format, GL_FLOAT, far);
  }
  PENUMBRA_TRY(check_gl("creating " + what + " (" + std::string(format.name()) + ", " +
                        std::to_string(levels) + " levels)"));
  return texture;
}

Result<FloatImage> read_texture(const Texture& texture, const TexelFormat& format, int level,
                                int width, int height, const std::string& what) {
  FloatImage image(width, height, format.channels);
  glGetTextureSubImage(texture.get(), level, 0, 0, 0, width, height, 1, format.pixel_format,
                       GL_FLOAT, static_cast<GLsizei>(image.data.size() * sizeof(float)),
                       image.data.data());
  PENUMBRA_TRY(check_gl("reading back " + what));
  return image;
}

}  // namespace penumbra::gl
