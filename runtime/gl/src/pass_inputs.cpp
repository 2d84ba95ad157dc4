#include "pass_inputs.hpp"

#include "textures.hpp"

namespace penumbra::gl {

void PassInputs::give(TextureId texture, const FloatImage& image, DepthFormat depth) {
  given_[texture] = Given{&image, depth};
}

void PassInputs::set(TextureId texture, GLuint name, const TexelFormat& format,
                     std::string origin) {
  drawn_[texture] = Drawn{name, &format, std::move(origin)};
}

void PassInputs::withdraw() {
  given_.clear();
  drawn_.clear();
}

void PassInputs::forget(const FloatImage& image) {
  std::erase_if(uploads_, [&](const Upload& upload) { return upload.image == &image; });
}

Result<GLuint> PassInputs::texture_for(TextureId texture, const TextureBinding& binding,
                                       const std::string& where) {
  auto format = texel_format(binding.format, where, "texture '" + binding.name + "'");
  if (!format) return format.error();
  if (const auto drawn = drawn_.find(texture); drawn != drawn_.end()) {
    if (drawn->second.format != *format) {
      return make_error(Error::Kind::bad_input, where,
                        "texture '" + binding.name + "' is read as " + binding.format +
                            " by the reflection, but " + drawn->second.origin + " is " +
                            std::string(drawn->second.format->name()));
    }
    return drawn->second.name;
  }
  const auto given = given_.find(texture);
  if (given == given_.end()) {
    return make_error(Error::Kind::bad_input, where,
                      "nothing supplies texture '" + binding.name + "' (" +
                          std::string(describe(texture).content) + ") to this pass");
  }
  const FloatImage& image = *given->second.image;
  const TexelFormat* stored = (*format)->format == TextureFormat::d32_float
                                  ? &depth_texel_format(given->second.depth)
                                  : *format;
  for (const Upload& earlier : uploads_) {
    if (earlier.image == &image && earlier.format == stored) return earlier.texture.get();
  }
  if (image.channels > stored->channels) {
    return make_error(Error::Kind::bad_input, where,
                      "texture '" + binding.name + "' has " + std::to_string(image.channels) +
                          " channels; its format " + binding.format + " holds " +
                          std::to_string(stored->channels));
  }
  auto uploaded = upload(image, *stored, "texture '" + binding.name + "'");
  if (!uploaded) return uploaded.error();
  uploads_.push_back({&image, stored, std::move(*uploaded)});
  return uploads_.back().texture.get();
}

}  // namespace penumbra::gl
