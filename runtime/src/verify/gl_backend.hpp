// The optional OpenGL path of verify: glsl330 and glsl450 text compiled by
// the GL driver (Mesa llvmpipe over EGL) instead of glslang. Present when the
// project is built with PENUMBRA_BUILD_GL; otherwise create() says why not.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "penumbra/runtime/program.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

class GlBackend {
 public:
  // Null when there is no GL path; `why_not` then says why. `device` selects
  // the GL device like penumbra::GlEngineOptions (verify passes "llvmpipe"
  // when Vulkan runs on lavapipe, so both paths use one rasterizer).
  static std::unique_ptr<GlBackend> create(const std::string& device, std::string& why_not);
  virtual ~GlBackend() = default;

  virtual std::string device() const = 0;
  virtual Result<FloatImage> run_query(std::string_view vertex_text, std::string_view fragment_text,
                                       const FloatImage& normalized_depth,
                                       const FloatImage& receivers, const ParamBlock& params) = 0;
};

}  // namespace penumbra
