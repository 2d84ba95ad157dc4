// verify's OpenGL path: glsl330 and glsl450 text compiled by the GL driver
// (Mesa llvmpipe over EGL) instead of glslang, bound by each pass's
// reflection in index.json as a GL engine binds it, on the scenes'
// normalized depth (the GL engine builds the min-max mip with the target's
// own passes when the query reads it). Present when the project is built
// with PENUMBRA_BUILD_GL; otherwise every run says why not.
#include <map>
#include <memory>
#include <span>
#include <vector>

#include "backend.hpp"

#ifdef PENUMBRA_HAS_GL
#include "penumbra/gl/engine.hpp"
#include "penumbra/library/pass_files.hpp"
#endif

namespace penumbra {
namespace {

bool glsl(Target target) {
  return target == Target::glsl330 || target == Target::glsl450;
}

// The GL path where it cannot run: every run on its targets says why.
class MissingGlBackend final : public Backend {
 public:
  explicit MissingGlBackend(std::string why) : why_(std::move(why)) {}

  std::string name() const override { return "gl"; }
  std::string device() const override { return {}; }
  std::string missing() const override { return why_; }
  bool executes(Target target) const override { return glsl(target); }
  Result<LoadedPasses> load(const Library& /*library*/, const LibraryVariant& entry,
                            Target /*target*/, const TargetScenes& /*scenes*/) override {
    return make_error(Error::Kind::device, entry.variant.name, why_);
  }
  Result<SceneOutput> run_deferred(const DeferredDraw& draw, const SceneFixture& /*fixture*/,
                                   Execution& /*execution*/) override {
    return make_error(Error::Kind::device, draw.entry->variant.name, why_);
  }

 private:
  std::string why_;
};

#ifdef PENUMBRA_HAS_GL

// One pass of a library for one target: its emitted texts and reflection.
struct GlPassTexts {
  std::string vert;
  std::string frag;
  PassReflection reflection;  // index.json's reflection.<pass>.<target>
};

// The passes that build the min-max mip.
struct GlMinmaxTexts {
  GlPassTexts init;    // minmax_init
  GlPassTexts reduce;  // minmax_reduce
};

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

// The min-max build passes of `entry` for `target` when its technique
// reads the mip; none otherwise. Errors as read_pass's.
Result<std::optional<GlMinmaxTexts>> read_gl_minmax(const Library& library,
                                                    const LibraryVariant& entry, Target target) {
  if (!uses_minmax_mip(entry.variant.technique)) return std::optional<GlMinmaxTexts>{};
  PENUMBRA_TRY_ASSIGN(GlPassTexts init, read_pass(library, entry, PassKind::minmax_init, target));
  PENUMBRA_TRY_ASSIGN(GlPassTexts reduce,
                      read_pass(library, entry, PassKind::minmax_reduce, target));
  return std::optional<GlMinmaxTexts>(GlMinmaxTexts{std::move(init), std::move(reduce)});
}

// Each of `passes` of `entry` for `target`. Errors as read_pass's.
Result<std::map<PassKind, GlPassTexts>> read_passes(const Library& library,
                                                    const LibraryVariant& entry, Target target,
                                                    std::span<const PassKind> passes) {
  std::map<PassKind, GlPassTexts> texts;
  for (PassKind pass : passes) {
    PENUMBRA_TRY_ASSIGN(GlPassTexts read, read_pass(library, entry, pass, target));
    texts.insert_or_assign(pass, std::move(read));
  }
  return texts;
}

// The engine reads the texts and reflection through references; the
// caller's outlive the call.
GlPass pass_of(const GlPassTexts& texts) {
  return {texts.vert, texts.frag, texts.reflection};
}

std::optional<GlMinmaxPasses> passes(const std::optional<GlMinmaxTexts>& texts) {
  if (!texts) return std::nullopt;
  return GlMinmaxPasses{pass_of(texts->init), pass_of(texts->reduce)};
}

class GlBackend final : public Backend {
 public:
  explicit GlBackend(std::unique_ptr<GlEngine> engine) : engine_(std::move(engine)) {}

  std::string name() const override { return "gl"; }
  std::string device() const override { return engine_->info().renderer; }
  std::string missing() const override { return {}; }
  bool executes(Target target) const override { return glsl(target); }

  Result<LoadedPasses> load(const Library& library, const LibraryVariant& entry, Target target,
                            const TargetScenes& /*scenes*/) override {
    // The GL engine builds the mip of the scene's map itself.
    std::vector<PassKind> passes = scene_passes(entry, /*builds_mip=*/true);
    PENUMBRA_TRY_ASSIGN(auto texts, read_passes(library, entry, target, passes));
    return LoadedPasses{
        execution(),
        [this, passes = std::move(passes),
         texts = std::make_shared<std::map<PassKind, GlPassTexts>>(std::move(texts))](
            const SceneFixture& fixture) -> Result<SceneOutput> {
          std::map<PassKind, GlPass> programs;
          for (const auto& [pass, text] : *texts) programs.emplace(pass, pass_of(text));
          PENUMBRA_TRY_ASSIGN(runtime::PassOutputs outputs,
                              engine_->run_passes(passes, programs, fixture.device_map(),
                                                  {.receivers = &fixture.receivers,
                                                   .scene_colour = &fixture.colour},
                                                  fixture.params, fixture.map_format()));
          return scene_output(std::move(outputs));
        }};
  }

  bool draws_surfaces(Target target) const override { return glsl(target); }
  Result<SurfacePicture> draw_surface(const SurfaceDraw& draw, const SceneFixture& fixture,
                                      Execution& out) override {
    out = execution();
    const std::string vertex =
        engine_vertex_shader(draw.target, draw.camera, draw.light, draw.vertex);
    const std::string fragment = engine_fragment_shader(
        draw.target, draw.reflection, draw.function_text, draw.light_depth, draw.call);
    PENUMBRA_TRY_ASSIGN(const std::optional<GlMinmaxTexts> minmax,
                        read_gl_minmax(*draw.library, *draw.entry, draw.target));
    PENUMBRA_TRY_ASSIGN(FloatImage clip,
                        engine_->run_surface({vertex, fragment, draw.reflection}, draw.triangles,
                                             fixture.device_map(), draw.width, draw.height,
                                             draw.params, fixture.map_format(), passes(minmax)));
    return SurfacePicture{std::move(clip), nullptr};
  }

  Result<SceneOutput> run_deferred(const DeferredDraw& draw, const SceneFixture& fixture,
                                   Execution& out) override {
    out = execution();
    PENUMBRA_TRY_ASSIGN(const GlPassTexts texts,
                        read_pass(*draw.library, *draw.entry, PassKind::deferred, draw.target));
    PENUMBRA_TRY_ASSIGN(const std::optional<GlMinmaxTexts> minmax,
                        read_gl_minmax(*draw.library, *draw.entry, draw.target));
    PENUMBRA_TRY_ASSIGN(
        auto output, engine_->run_deferred(pass_of(texts), fixture.device_map(), draw.camera_depth,
                                           draw.params, fixture.map_format(), passes(minmax)));
    return scene_output(std::move(output.visibility), std::move(output.texel_reads));
  }

 private:
  static Execution execution() { return {"the OpenGL driver's GLSL compiler", {}}; }

  std::unique_ptr<GlEngine> engine_;
};

#endif

}  // namespace

std::unique_ptr<Backend> gl_backend(const std::string& not_requested, const std::string& device) {
  if (!not_requested.empty()) return std::make_unique<MissingGlBackend>(not_requested);
#ifdef PENUMBRA_HAS_GL
  auto engine = GlEngine::create(GlEngineOptions{.device = device}, ignore_diagnostics());
  if (!engine) {
    return std::make_unique<MissingGlBackend>("no OpenGL context: " + engine.error().to_string());
  }
  return std::make_unique<GlBackend>(std::move(*engine));
#else
  static_cast<void>(device);
  return std::make_unique<MissingGlBackend>(
      "built without OpenGL (PENUMBRA_BUILD_GL=OFF or EGL/GL not found at configure time)");
#endif
}

}  // namespace penumbra
