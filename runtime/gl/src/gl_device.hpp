// GlDevice: the pass driver's Device (penumbra/runtime/device.hpp) on the
// current GL context. Programs are GLSL text prepared by their reflection;
// an uploaded image is kept on the host and uploaded on first use in the
// format of the binding that reads it (the map as a depth or an R32F
// texture); every draw's GL work is finished when it returns. The OpenGL
// runtime takes its maps as images: it draws no depth pass.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl_names.hpp"
#include "minmax_mip.hpp"
#include "pass_inputs.hpp"
#include "pass_program.hpp"
#include "penumbra/runtime/device.hpp"

namespace penumbra::gl {

class GlDevice final : public runtime::Device {
 public:
  // On the GL context current on this thread.
  GlDevice();

  // `pass` prepared as the `kind` pass. Errors: prepare_pass's.
  Result<runtime::Program> load(const GlPass& pass, PassKind kind);
  // An engine's own program drawing triangles (3 floats per vertex), as `where`.
  Result<runtime::Program> load_surface(const GlPass& pass, std::string where);
  // What load() prepared.
  const PassProgram& program(runtime::Program program) const;

  // The map's normalized depth, read where the reflection says D32 as a
  // `format` depth texture (an engine's D24 or D16 map).
  Result<runtime::Texture> upload_map(const FloatImage& normalized_depth, DepthFormat format);

  Result<runtime::Texture> upload(TextureId as, const FloatImage& image) override;
  Result<runtime::Drawn> draw(const runtime::Draw& draw) override;
  Result<runtime::Texture> gather_mip(runtime::Texture map,
                                      std::span<const runtime::Texture> levels) override;
  Result<std::vector<FloatImage>> read_all(std::span<const runtime::Texture> textures) override;
  void release(runtime::Texture texture) override;

 private:
  // A host image, a pass's target (with its format and whose it is), or a mip.
  struct Held {
    std::unique_ptr<FloatImage> image;
    DepthFormat depth = DepthFormat::d32_float;
    Texture target;
    const TexelFormat* format = nullptr;
    std::string origin;  // "the query pass's target", in errors
    std::optional<MinmaxMip> mip;
  };

  runtime::Texture hold(Held held, int width, int height);
  Result<FloatImage> read_one(runtime::Texture texture);
  Result<Held*> find(runtime::Texture texture, std::string_view where);
  Status offer(const runtime::Draw& draw);

  bool software_ = false;              // llvmpipe: full-screen draws pass_through_blend
  std::vector<PassProgram> programs_;  // Program::id - 1
  std::map<int, Held> textures_;
  PassInputs inputs_;  // its uploads serve every draw
  int next_id_ = 1;
};

}  // namespace penumbra::gl
