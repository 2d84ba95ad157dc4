// verify's Direct3D bytecode path: what a Direct3D engine loads (each HLSL
// target's .d3dbc/.dxbc files) translated to SPIR-V by vkd3d-compiler, as
// Proton does, and run on the Vulkan engine over the scenes' maps. The
// engine binds the translation by the reflection's registers.
#include <memory>

#include "backend.hpp"
#include "penumbra/compiler/targets.hpp"

namespace penumbra {
namespace {

class BytecodeBackend final : public Backend {
 public:
  BytecodeBackend(Engine& engine, BytecodeTranslator translator)
      : engine_(engine), translator_(std::move(translator)) {}

  std::string name() const override { return "bytecode"; }
  std::string device() const override { return engine_.device_info().name; }
  std::string missing() const override {
    if (!translator_.compiler.empty()) return {};
    return "no HLSL compiler to translate the Direct3D bytecode (give --hlsl-compiler PATH or "
           "PENUMBRA_HLSL_COMPILER: vkd3d-compiler 2.1 or newer)";
  }
  // Every target a Direct3D engine loads as bytecode.
  bool executes(Target target) const override {
    return bytecode_format(target, ShaderStage::fragment).has_value();
  }
  std::string not_executed(const LibraryVariant& entry, Target target) const override {
    return lacking_bytecode(entry, target);
  }

  Result<LoadedPasses> load(const Library& library, const LibraryVariant& entry, Target target,
                            const TargetScenes& scenes) override {
    return load_on_engine(engine_, entry, scenes, [&](PassKind pass) {
      return load_bytecode_executable(library, entry, pass, target, translator_);
    });
  }

  // An engine's own HLSL compiled to bytecode by vkd3d-compiler, then
  // translated, as a Direct3D engine's shaders reach Vulkan under Proton.
  bool draws_surfaces(Target target) const override {
    return executes(target) && missing().empty();
  }
  Result<SurfacePicture> draw_surface(const SurfaceDraw& draw, const SceneFixture& fixture,
                                      Execution& execution) override {
    PassProgram program;
    // The bytecode flips y as the HLSL text it was compiled from does.
    program.d3d_viewport = true;
    program.d3d_bytecode = true;
    return surface_on_engine(
        engine_, draw, fixture, std::move(program),
        [&](ShaderStage stage, const std::string& text, const std::string& name) {
          return compile_bytecode_stage(translator_, draw.target, stage, text, name, execution);
        });
  }

  Result<SceneOutput> run_deferred(const DeferredDraw& draw, const SceneFixture& fixture,
                                   Execution& execution) override {
    PENUMBRA_TRY_ASSIGN(ExecutableProgram loaded,
                        load_bytecode_executable(*draw.library, *draw.entry, PassKind::deferred,
                                                 draw.target, translator_));
    execution = std::move(loaded.execution);
    return deferred_on_engine(engine_, draw, fixture, loaded.program);
  }

 private:
  Engine& engine_;
  BytecodeTranslator translator_;
};

}  // namespace

std::string lacking_bytecode(const LibraryVariant& entry, Target target) {
  const auto query = entry.passes.find(PassKind::query);
  if (query == entry.passes.end() || !query->second.contains(target)) return {};
  const PassFiles& files = query->second.at(target);
  if (files.vert_bytecode && files.frag_bytecode) return {};
  return "the library has no " + std::string(to_string(target)) +
         " bytecode (built without an HLSL compiler: penumbra build --hlsl-compiler PATH)";
}

std::unique_ptr<Backend> bytecode_backend(Engine& engine, BytecodeTranslator translator) {
  return std::make_unique<BytecodeBackend>(engine, std::move(translator));
}

}  // namespace penumbra
