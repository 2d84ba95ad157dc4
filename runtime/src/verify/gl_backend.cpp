#include "verify/gl_backend.hpp"

#ifdef PENUMBRA_HAS_GL
#include "penumbra/gl/engine.hpp"
#endif

namespace penumbra {

#ifdef PENUMBRA_HAS_GL
namespace {

// The engine reads the texts through views; the caller's strings outlive the call.
GlPass pass(const GlPassTexts& texts) {
  return {texts.vert, texts.frag};
}

class MesaGlBackend final : public GlBackend {
 public:
  explicit MesaGlBackend(std::unique_ptr<GlEngine> engine) : engine_(std::move(engine)) {}
  std::string device() const override { return engine_->info().renderer; }
  Result<QueryOutput> run_query(const GlQueryTexts& texts, const FloatImage& normalized_depth,
                                const FloatImage& receivers, const ParamBlock& params) override {
    GlQueryPasses passes{pass(texts.query), std::nullopt};
    if (texts.minmax) {
      passes.minmax = GlMinmaxPasses{pass(texts.minmax->init), pass(texts.minmax->reduce)};
    }
    auto output = engine_->run_query(passes, normalized_depth, receivers, params);
    if (!output) return output.error();
    return QueryOutput{std::move(output->visibility), std::move(output->texel_reads), std::nullopt};
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
