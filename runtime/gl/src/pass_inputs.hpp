// The images a draw reads, by shader_contract.hpp's TextureId (find_texture
// of the reflection's name): the caller's images, uploaded on first use in
// the format of the binding that reads them (and kept for later draws), and
// the textures earlier passes drew.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gl_names.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"
#include "texel_formats.hpp"

namespace penumbra::gl {

class PassInputs {
 public:
  // `image` is read as `texture`; it must outlive this. One image given for
  // two textures (the map as shadow_depth and shadow_cmp) is uploaded once
  // per format. Where the binding is GL_DEPTH_COMPONENT32F, the texture is
  // `depth`'s (an engine's D24 or D16 map).
  void give(TextureId texture, const FloatImage& image, DepthFormat depth = DepthFormat::d32_float);

  // `name`, a texture in `format` an earlier pass drew (`origin` says which,
  // for errors), is read as `texture`, replacing what was read as it.
  void set(TextureId texture, GLuint name, const TexelFormat& format, std::string origin);

  // Forgets what was given and set, for the next draw; the uploads stay.
  void withdraw();
  // Drops the uploads of `image`, which is about to be freed.
  void forget(const FloatImage& image);

  // The texture to bind to `binding`, which reads `texture`. Errors
  // (bad_input, `where`): nothing supplies it, its format differs from the
  // binding's, or the image has more channels than the binding's format;
  // device for a GL error uploading it.
  Result<GLuint> texture_for(TextureId texture, const TextureBinding& binding,
                             const std::string& where);

 private:
  struct Upload {
    const FloatImage* image;
    const TexelFormat* format;
    Texture texture;
  };
  struct Drawn {
    GLuint name;
    const TexelFormat* format;
    std::string origin;
  };
  struct Given {
    const FloatImage* image;
    DepthFormat depth;
  };
  std::map<TextureId, Given> given_;
  std::vector<Upload> uploads_;
  std::map<TextureId, Drawn> drawn_;
};

}  // namespace penumbra::gl
