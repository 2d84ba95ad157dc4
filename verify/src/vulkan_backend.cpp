// verify's Vulkan path: every target's files (the .spv as built, or the text
// through glslang's front ends) on the Vulkan engine that prepared the
// scenes, on their maps as rendered; load_on_engine() runs them, for the
// bytecode path too.
#include <map>
#include <memory>
#include <vector>

#include "backend.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra {
namespace {

class VulkanBackend final : public Backend {
 public:
  explicit VulkanBackend(Engine& engine) : engine_(engine) {}

  std::string name() const override { return "vulkan"; }
  std::string device() const override { return engine_.device_info().name; }
  std::string missing() const override { return {}; }
  bool executes(Target /*target*/) const override { return true; }

  Result<LoadedPasses> load(const Library& library, const LibraryVariant& entry, Target target,
                            const TargetScenes& scenes) override {
    return load_on_engine(engine_, entry, scenes, [&](PassKind pass) {
      return load_executable(library, entry, pass, target);
    });
  }

  // Every text target, its stages through the target's glslang front end.
  bool draws_surfaces(Target target) const override { return target != Target::spirv; }
  Result<SurfacePicture> draw_surface(const SurfaceDraw& draw, const SceneFixture& fixture,
                                      Execution& execution) override {
    PassProgram program;
    program.d3d_viewport = traits(draw.target).is_hlsl;
    program.gl_clip_depth = !traits(draw.target).is_hlsl;
    return surface_on_engine(
        engine_, draw, fixture, std::move(program),
        [&](ShaderStage stage, const std::string& text, const std::string& name) {
          return compile_text_stage(draw.target, stage, text, name, execution);
        });
  }

  Result<SceneOutput> run_deferred(const DeferredDraw& draw, const SceneFixture& fixture,
                                   Execution& execution) override {
    PENUMBRA_TRY_ASSIGN(ExecutableProgram loaded, load_executable(*draw.library, *draw.entry,
                                                                  PassKind::deferred, draw.target));
    execution = std::move(loaded.execution);
    return deferred_on_engine(engine_, draw, fixture, loaded.program);
  }

 private:
  Engine& engine_;
};

// The mip an engine builds of its map before it draws, for a technique that
// reads it: on the fixture's map, with the target's own build passes (the
// OpenGL and Wine paths build theirs on their own maps).
Status build_stage_minmax(Engine& engine, const Library& library, const LibraryVariant& entry,
                          Target target, const SceneFixture& fixture) {
  if (!uses_minmax_mip(entry.variant.technique)) return {};
  PENUMBRA_TRY(build_library_minmax(engine, library, entry, target, *fixture.map, fixture.params));
  return {};
}

}  // namespace

Result<SurfacePicture> surface_on_engine(Engine& engine, const SurfaceDraw& draw,
                                         const SceneFixture& fixture, PassProgram program,
                                         const SurfaceStageCompiler& compile) {
  program.target = draw.target;
  program.reflection = draw.reflection;
  PENUMBRA_TRY_ASSIGN(
      program.vert, compile(ShaderStage::vertex,
                            engine_vertex_shader(draw.target, draw.camera, draw.light, draw.vertex),
                            draw.where + " (engine vertex stage)"));
  PENUMBRA_TRY_ASSIGN(
      program.frag, compile(ShaderStage::fragment,
                            engine_fragment_shader(draw.target, draw.reflection, draw.function_text,
                                                   draw.light_depth, draw.call),
                            draw.where + " (engine fragment stage)"));
  PENUMBRA_TRY(build_stage_minmax(engine, *draw.library, *draw.entry, draw.target, fixture));
  PENUMBRA_TRY_ASSIGN(FloatImage clip, engine.run_surface(program, draw.triangles, *fixture.map,
                                                          draw.width, draw.height, draw.params));
  return SurfacePicture{std::move(clip), nullptr};
}

Result<SceneOutput> deferred_on_engine(Engine& engine, const DeferredDraw& draw,
                                       const SceneFixture& fixture, const PassProgram& program) {
  PENUMBRA_TRY(build_stage_minmax(engine, *draw.library, *draw.entry, draw.target, fixture));
  PENUMBRA_TRY_ASSIGN(QueryOutput gpu,
                      engine.run_deferred(program, *fixture.map, draw.camera_depth, draw.params));
  return scene_output(std::move(gpu.visibility), std::move(gpu.texel_reads));
}

Result<LoadedPasses> load_on_engine(Engine& engine, const LibraryVariant& entry,
                                    const TargetScenes& scenes, const PassLoader& load) {
  // The passes read the mip the target's own passes built on each map.
  if (uses_minmax_mip(entry.variant.technique) && scenes.minmax && !*scenes.minmax) {
    return scenes.minmax->error();
  }
  const std::vector<PassKind> passes = scene_passes(entry, /*builds_mip=*/false);
  PENUMBRA_TRY_ASSIGN(LoadedPrograms programs, load_passes(passes, load));
  auto loaded = std::make_shared<const LoadedPrograms>(std::move(programs));
  return LoadedPasses{
      loaded->at(passes.front()).execution,
      [&engine, loaded, passes](const SceneFixture& fixture) -> Result<SceneOutput> {
        PENUMBRA_TRY_ASSIGN(
            runtime::PassOutputs outputs,
            engine.run_passes(passes, program_map(*loaded), *fixture.map,
                              {.receivers = &fixture.receivers, .scene_colour = &fixture.colour},
                              fixture.params));
        return scene_output(std::move(outputs));
      }};
}

std::unique_ptr<Backend> vulkan_backend(Engine& engine) {
  return std::make_unique<VulkanBackend>(engine);
}

}  // namespace penumbra
