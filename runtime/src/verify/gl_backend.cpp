#include "verify/gl_backend.hpp"

#ifdef PENUMBRA_HAS_GL
#include "penumbra/gl/engine.hpp"
#endif

namespace penumbra {

#ifdef PENUMBRA_HAS_GL
namespace {

class MesaGlBackend final : public GlBackend {
 public:
  explicit MesaGlBackend(std::unique_ptr<GlEngine> engine) : engine_(std::move(engine)) {}
  std::string device() const override { return engine_->info().renderer; }
  Result<FloatImage> run_query(std::string_view vertex_text, std::string_view fragment_text,
                               const FloatImage& normalized_depth, const FloatImage& receivers,
                               const ParamBlock& params) override {
    return engine_->run_query(vertex_text, fragment_text, normalized_depth, receivers, params);
  }

 private:
  std::unique_ptr<GlEngine> engine_;
};

}  // namespace

std::unique_ptr<GlBackend> GlBackend::create(const std::string& device, std::string& why_not) {
  auto engine = GlEngine::create(GlEngineOptions{.device = device}, ignore_diagnostics());
  if (!engine) {
    why_not = "no OpenGL context: " + engine.error().to_string();
    return nullptr;
  }
  return std::make_unique<MesaGlBackend>(std::move(*engine));
}

#else

std::unique_ptr<GlBackend> GlBackend::create(const std::string& /*device*/, std::string& why_not) {
  why_not = "built without OpenGL (PENUMBRA_BUILD_GL=OFF or EGL/GL not found at configure time)";
  return nullptr;
}

#endif

}  // namespace penumbra
