// verify's Direct3D runtime paths: each HLSL target's bytecode loaded by a
// real Direct3D runtime (Wine's d3d9, d3d10 and d3d11 over llvmpipe, under
// its own Xvfb and Wine prefix: penumbra::d3d), bound from the reflection
// alone as a Direct3D engine binds it. Unlike the Vulkan-hosted paths, each
// draws every scene's map with the target's own depth pass on the runtime
// itself, so the runtime's rasterization rules (D3D9's pixel centres) decide
// what the map and the queries hold; the map is checked against the ray
// cast, and the reference reads it.
#include <map>
#include <memory>
#include <mutex>

#include "backend.hpp"
#include "engine_shaders.hpp"
#include "map_placement.hpp"
#include "penumbra/d3d/engine.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/support/scratch_file.hpp"

namespace penumbra {
namespace {

// One Wine session for the three runtimes of every device thread, started
// when a run first needs it.
class SharedSession {
 public:
  Result<std::shared_ptr<WineSession>> get() {
    const std::lock_guard lock(mutex_);
    if (!session_) session_ = WineSession::start(WineSession::options_from_environment());
    return *session_;
  }

 private:
  std::mutex mutex_;
  std::optional<Result<std::shared_ptr<WineSession>>> session_;
};

// A scene's map drawn on the runtime: kept for every variant after the first.
struct RuntimeMap {
  D3dMap map;
  std::shared_ptr<const FloatImage> stored;  // map.normalized
  std::shared_ptr<const FloatImage> linear;  // the same as linear z
  bool checked = false;                      // its DepthCheck went out with a run
};

Result<D3dPass> bytecode_pass(const Library& library, const LibraryVariant& entry, PassKind pass,
                              Target target) {
  const auto files = entry.passes.find(pass);
  const auto reflection = entry.reflection.find(pass);
  if (files == entry.passes.end() || !files->second.contains(target) ||
      reflection == entry.reflection.end() || !reflection->second.contains(target)) {
    return make_error(Error::Kind::bad_input, entry.variant.name,
                      "index.json has no " + std::string(to_string(pass)) + " pass for " +
                          std::string(to_string(target)));
  }
  const PassFiles& stage_files = files->second.at(target);
  if (!stage_files.vert_bytecode || !stage_files.frag_bytecode) {
    return make_error(Error::Kind::bad_input, entry.variant.name,
                      "the library has no " + std::string(to_string(target)) +
                          " bytecode for its " + std::string(to_string(pass)) + " pass");
  }
  return D3dPass{library.root / stage_files.vert_bytecode->path,
                 library.root / stage_files.frag_bytecode->path, reflection->second.at(target)};
}

// `entry`'s min-max build passes for `target` when its technique reads the
// mip; none otherwise. Errors as bytecode_pass's.
Result<std::optional<D3dMinmaxPasses>> minmax_passes(const Library& library,
                                                     const LibraryVariant& entry, Target target) {
  if (!uses_minmax_mip(entry.variant.technique)) return std::optional<D3dMinmaxPasses>{};
  PENUMBRA_TRY_ASSIGN(D3dPass init, bytecode_pass(library, entry, PassKind::minmax_init, target));
  PENUMBRA_TRY_ASSIGN(D3dPass reduce,
                      bytecode_pass(library, entry, PassKind::minmax_reduce, target));
  return std::optional<D3dMinmaxPasses>(D3dMinmaxPasses{init, reduce});
}

// The passes a run needs, with the records they point into: the depth
// pass that draws the runtime's own map, and the scene's passes on it.
struct RuntimePasses {
  D3dPass depth;
  std::vector<PassKind> scene;
  std::map<PassKind, D3dPass> programs;
};

Result<RuntimePasses> runtime_passes(const Library& library, const LibraryVariant& entry,
                                     Target target) {
  PENUMBRA_TRY_ASSIGN(D3dPass depth, bytecode_pass(library, entry, PassKind::depth, target));
  // The runtime builds the mip of its own map.
  RuntimePasses passes{depth, scene_passes(entry, /*builds_mip=*/true), {}};
  for (PassKind pass : passes.scene) {
    PENUMBRA_TRY_ASSIGN(D3dPass program, bytecode_pass(library, entry, pass, target));
    passes.programs.emplace(pass, program);
  }
  return passes;
}

class WineBackend final : public Backend {
 public:
  WineBackend(D3dRuntime runtime, std::shared_ptr<SharedSession> session, std::string missing,
              BytecodeTranslator compiler)
      : runtime_(runtime),
        session_(std::move(session)),
        missing_(std::move(missing)),
        compiler_(std::move(compiler)) {}

  std::string name() const override { return std::string(to_string(runtime_)); }
  // Wine names the adapter its own way (a GeForce whatever GL renders with).
  std::string device() const override {
    return engine_ && !engine_->description().empty() ? "Wine's " + engine_->description() : "";
  }
  std::string missing() const override { return missing_; }
  bool executes(Target target) const override { return runtime_for(target) == runtime_; }
  std::string not_executed(const LibraryVariant& entry, Target target) const override {
    return lacking_bytecode(entry, target);
  }

  void expect(Target target) override {
    if (executes(target) && missing_.empty()) static_cast<void>(launch());
  }

  Result<LoadedPasses> load(const Library& library, const LibraryVariant& entry, Target target,
                            const TargetScenes& /*scenes*/) override {
    PENUMBRA_TRY(start());
    PENUMBRA_TRY_ASSIGN(RuntimePasses passes, runtime_passes(library, entry, target));
    // The passes point into `entry`'s records, which outlive the run.
    auto shared = std::make_shared<RuntimePasses>(std::move(passes));
    return LoadedPasses{
        Execution{"the " + name() + " runtime (Wine) loading the bytecode", {}},
        [this, shared, target](const SceneFixture& fixture) -> Result<SceneOutput> {
          PENUMBRA_TRY_ASSIGN(RuntimeMap * drawn, map_of(shared->depth, fixture));
          PENUMBRA_TRY_ASSIGN(runtime::PassOutputs outputs,
                              engine_->run_passes(shared->scene, shared->programs, drawn->map,
                                                  {.receivers = &fixture.receivers,
                                                   .scene_colour = &fixture.colour},
                                                  fixture.params));
          SceneOutput output = scene_output(std::move(outputs));
          output.own_stored_depth = drawn->stored;
          output.own_linear_depth = drawn->linear;
          if (!drawn->checked) {
            const DepthFormat format = fixture.map_format();
            output.own_depth_check =
                check_depth(*fixture.depth_truth, fixture.scene, target, *drawn->linear, name(),
                            format != DepthFormat::d32_float ? fixture.encoded : std::nullopt);
            output.own_depth_check->map_encoding = fixture.depth_check.map_encoding;
            output.own_depth_check->map_format = format;
            drawn->checked = true;
          }
          return output;
        }};
  }

  // An engine's own HLSL compiled to bytecode by vkd3d-compiler, as its
  // build would, on the scene's map drawn by this runtime.
  bool draws_surfaces(Target target) const override {
    return executes(target) && missing_.empty() && !compiler_.compiler.empty();
  }
  Result<SurfacePicture> draw_surface(const SurfaceDraw& draw, const SceneFixture& fixture,
                                      Execution& execution) override {
    PENUMBRA_TRY(start());
    PENUMBRA_TRY_ASSIGN(const D3dPass depth,
                        bytecode_pass(*draw.library, *draw.entry, PassKind::depth, draw.target));
    PENUMBRA_TRY_ASSIGN(RuntimeMap * drawn, map_of(depth, fixture));
    VertexOptions vertex = draw.vertex;
    vertex.half_pixel_offset = runtime_ == D3dRuntime::d3d9;
    const ScratchFile vs("surface", ".vs"), ps("surface", ".ps");
    PENUMBRA_TRY(
        compile_hlsl_bytecode(compiler_, draw.target, ShaderStage::vertex,
                              engine_vertex_shader(draw.target, draw.camera, draw.light, vertex),
                              draw.where + " (engine vertex stage)", vs.path()));
    PENUMBRA_TRY(compile_hlsl_bytecode(
        compiler_, draw.target, ShaderStage::fragment,
        engine_fragment_shader(draw.target, draw.reflection, draw.function_text, draw.light_depth,
                               draw.call),
        draw.where + " (engine fragment stage)", ps.path()));
    execution = {"vkd3d-compiler's bytecode loaded by the " + name() + " runtime (Wine)", {}};
    PENUMBRA_TRY_ASSIGN(const auto minmax, minmax_passes(*draw.library, *draw.entry, draw.target));
    PENUMBRA_TRY_ASSIGN(
        FloatImage clip,
        engine_->run_surface({vs.path(), ps.path(), draw.reflection}, draw.triangles, drawn->map,
                             draw.width, draw.height, draw.params, minmax));
    return SurfacePicture{std::move(clip), drawn->stored};
  }

  Result<SceneOutput> run_deferred(const DeferredDraw& draw, const SceneFixture& fixture,
                                   Execution& execution) override {
    PENUMBRA_TRY(start());
    const auto pass = [&](PassKind kind) {
      return bytecode_pass(*draw.library, *draw.entry, kind, draw.target);
    };
    PENUMBRA_TRY_ASSIGN(const D3dPass depth, pass(PassKind::depth));
    PENUMBRA_TRY_ASSIGN(const D3dPass deferred, pass(PassKind::deferred));
    PENUMBRA_TRY_ASSIGN(const auto minmax, minmax_passes(*draw.library, *draw.entry, draw.target));
    PENUMBRA_TRY_ASSIGN(RuntimeMap * drawn, map_of(depth, fixture));
    execution = {"the " + name() + " runtime (Wine) loading the bytecode", {}};
    PENUMBRA_TRY_ASSIGN(auto output, engine_->run_deferred(deferred, drawn->map, draw.camera_depth,
                                                           draw.params, minmax));
    SceneOutput out = scene_output(std::move(output.visibility), std::move(output.texel_reads));
    out.own_stored_depth = drawn->stored;
    out.own_linear_depth = drawn->linear;
    return out;
  }

 private:
  // The host started, once: a failure to start is kept for every later call.
  Status launch() {
    if (engine_) return {};
    if (launch_error_) return *launch_error_;
    auto session = session_->get();
    if (!session) return *(launch_error_ = session.error());
    D3dEngineOptions options;
    options.runtime = runtime_;
    auto engine = D3dEngine::launch(*session, options);
    if (!engine) return *(launch_error_ = engine.error());
    engine_ = std::move(*engine);
    return {};
  }

  // The host started and its device made.
  Status start() {
    PENUMBRA_TRY(launch());
    return engine_->ready();
  }

  // The fixture's scene drawn by the target's depth pass on this runtime,
  // once per scene and map encoding.
  Result<RuntimeMap*> map_of(const D3dPass& depth, const SceneFixture& fixture) {
    // The fixture's depth format: an engine's D24 or D16 map where the
    // target reads a depth texture (hlsl_dx9's map is its R32F target).
    const DepthFormat format = fixture.map_format();
    const std::string key =
        fixture.scene.name + "@" + std::to_string(fixture.scene.map_width) + "x" +
        std::to_string(fixture.scene.map_height) + " " +
        std::string(to_string(depth.reflection.map_encoding.value_or(MapEncoding::linear))) + " " +
        std::string(to_string(format));
    auto known = maps_.find(key);
    if (known == maps_.end()) {
      PENUMBRA_TRY_ASSIGN(
          D3dMap map,
          engine_->render_depth(depth, reference::triangles(fixture.scene), fixture.scene.map_width,
                                fixture.scene.map_height, fixture.params, format));
      auto stored = std::make_shared<const FloatImage>(map.normalized);
      auto linear = std::make_shared<const FloatImage>(
          linear_depth_of(*stored, fixture.encoded, depth_scale_for(fixture.scene.far_z)));
      known =
          maps_
              .emplace(key, RuntimeMap{std::move(map), std::move(stored), std::move(linear), false})
              .first;
    }
    RuntimeMap& own = known->second;
    const MapLayout layout = fixture.layout();
    if (layout == MapLayout::single) return &own;
    // An atlas or array variant's: the map this runtime drew, placed as the
    // fixture's is, which then reports the map's depth check.
    const std::string placed_key = key + " " + std::string(to_string(layout)) + " " +
                                   std::to_string(fixture.placement.slot) + "/" +
                                   std::to_string(fixture.placement.slots);
    if (auto placed = maps_.find(placed_key); placed != maps_.end()) return &placed->second;
    PENUMBRA_TRY_ASSIGN(D3dMap uploaded,
                        engine_->upload_map(place_map(fixture, *own.stored, fixture.placement)));
    RuntimeMap in_place{std::move(uploaded), own.stored, own.linear, own.checked};
    own.checked = true;
    return &maps_.emplace(placed_key, std::move(in_place)).first->second;
  }

  D3dRuntime runtime_;
  std::shared_ptr<SharedSession> session_;
  std::string missing_;
  BytecodeTranslator compiler_;  // compiles an engine's own HLSL (draw_surface)
  std::unique_ptr<D3dEngine> engine_;
  std::optional<Error> launch_error_;  // why the host could not start
  std::map<std::string, RuntimeMap> maps_;
};

// Why the runtimes cannot run here, or empty: checked without starting anything.
std::string why_missing(const std::string& not_requested) {
  if (!not_requested.empty()) return not_requested;
  if (std::string host = why_no_d3d_host(); !host.empty()) return host;
  const auto session = WineSession::options_from_environment();
  if (auto missing = WineSession::missing_programs(session); !missing.empty()) return missing;
  return {};
}

// The session of the runtimes' backends alive now, or a new one: one Wine
// prefix and Xvfb for the three, however many times they are made.
std::shared_ptr<SharedSession> shared_session() {
  static std::mutex mutex;
  static std::weak_ptr<SharedSession> current;
  const std::lock_guard lock(mutex);
  std::shared_ptr<SharedSession> session = current.lock();
  if (!session) {
    session = std::make_shared<SharedSession>();
    current = session;
  }
  return session;
}

}  // namespace

std::unique_ptr<Backend> wine_backend(D3dRuntime runtime, const std::string& not_requested,
                                      BytecodeTranslator compiler) {
  return std::make_unique<WineBackend>(runtime, shared_session(), why_missing(not_requested),
                                       std::move(compiler));
}

}  // namespace penumbra
