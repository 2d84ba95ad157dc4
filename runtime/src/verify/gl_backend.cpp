#include "verify/gl_backend.hpp"

#include "penumbra/runtime/library_programs.hpp"

#ifdef PENUMBRA_HAS_GL
#include "penumbra/gl/engine.hpp"
#endif

namespace penumbra {
namespace {

Result<GlPassTexts> read_pass(const Library& library, const LibraryVariant& entry, PassKind pass,
                              Target target) {
  const auto by_pass = entry.reflection.find(pass);
  if (by_pass == entry.reflection.end() || !by_pass->second.contains(target)) {
    return make_error(Error::Kind::bad_input, entry.variant.name,
                      "index.json has no reflection." + std::string(to_string(pass)) + "." +
                          std::string(to_string(target)) + " to bind the pass by");
  }
  auto vert = read_pass_file(library, entry, pass, target, ShaderStage::vertex);
  if (!vert) return vert.error();
  auto frag = read_pass_file(library, entry, pass, target, ShaderStage::fragment);
  if (!frag) return frag.error();
  return GlPassTexts{std::move(*vert), std::move(*frag), by_pass->second.at(target)};
}

}  // namespace

Result<GlQueryTexts> read_gl_query(const Library& library, const LibraryVariant& entry,
                                   Target target) {
  auto query = read_pass(library, entry, PassKind::query, target);
  if (!query) return query.error();
  GlQueryTexts texts{std::move(*query), std::nullopt};
  if (uses_minmax_mip(entry.variant.technique)) {
    auto init = read_pass(library, entry, PassKind::minmax_init, target);
    if (!init) return init.error();
    auto reduce = read_pass(library, entry, PassKind::minmax_reduce, target);
    if (!reduce) return reduce.error();
    texts.minmax = GlMinmaxTexts{std::move(*init), std::move(*reduce)};
  }
  return texts;
}

Result<GlScreenBlurTexts> read_gl_screen_blur(const Library& library, const LibraryVariant& entry,
                                              Target target) {
  GlScreenBlurTexts texts;
  for (const auto& [kind, pass] :
       {std::pair{PassKind::query, &texts.query}, std::pair{PassKind::blur_h, &texts.blur_h},
        std::pair{PassKind::blur_v, &texts.blur_v},
        std::pair{PassKind::composite, &texts.composite}}) {
    auto read = read_pass(library, entry, kind, target);
    if (!read) return read.error();
    *pass = std::move(*read);
  }
  return texts;
}

#ifdef PENUMBRA_HAS_GL
namespace {

// The engine reads the texts and reflection through references; the
// caller's outlive the call.
GlPass pass(const GlPassTexts& texts) {
  return {texts.vert, texts.frag, texts.reflection};
}

class MesaGlBackend final : public GlBackend {
 public:
  explicit MesaGlBackend(std::unique_ptr<GlEngine> engine) : engine_(std::move(engine)) {}
  std::string device() const override { return engine_->info().renderer; }

  Result<QueryOutput> run_query(const GlQueryTexts& texts, const FloatImage& normalized_depth,
                                const FloatImage& receivers, const ParamBlock& params) override {
    std::optional<GlMinmaxPasses> minmax;
    if (texts.minmax) minmax.emplace(pass(texts.minmax->init), pass(texts.minmax->reduce));
    auto output =
        engine_->run_query({pass(texts.query), minmax}, normalized_depth, receivers, params);
    if (!output) return output.error();
    return QueryOutput{std::move(output->visibility), std::move(output->texel_reads), std::nullopt};
  }

  Result<ScreenBlurOutput> run_screen_blur(const GlScreenBlurTexts& texts,
                                           const FloatImage& normalized_depth,
                                           const FloatImage& receivers,
                                           const FloatImage& scene_colour,
                                           const ParamBlock& params) override {
    auto output = engine_->run_screen_blur(
        {pass(texts.query), pass(texts.blur_h), pass(texts.blur_v), pass(texts.composite)},
        normalized_depth, receivers, scene_colour, params);
    if (!output) return output.error();
    return ScreenBlurOutput{std::move(output->factor),    std::move(output->texel_reads),
                            std::move(output->blurred_h), std::move(output->blurred),
                            std::move(output->composite), std::nullopt};
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
