// Loading a built library's passes as runnable programs.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "penumbra/compiler/bytecode_frontend.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "penumbra/vulkan/program.hpp"

namespace penumbra {

// How a target's files reached the device: recorded in verify.json.
struct Execution {
  std::string front_end;           // "SPIR-V as built", or the front end that compiled the text
  std::vector<std::string> shims;  // text rewrites the front end needed (docs/frontends.md)
};

struct ExecutableProgram {
  PassProgram program;
  Execution execution;
};

// One stage of `target`'s text (an emitted file, or an engine's own shader
// around a function form) compiled by the target's glslang front end and
// reflected; `execution` gains the front end and any shims it needed.
// `name` names the text in errors.
Result<StageCode> compile_text_stage(Target target, ShaderStage stage, std::string_view text,
                                     const std::string& name, Execution& execution);

// One stage of an HLSL target's text compiled to the target's Direct3D
// bytecode and translated to SPIR-V by `translator`'s vkd3d-compiler
// (compile_hlsl_to_spirv), and reflected; `execution`'s front end says so.
Result<StageCode> compile_bytecode_stage(const BytecodeTranslator& translator, Target target,
                                         ShaderStage stage, const std::string& text,
                                         const std::string& name, Execution& execution);

// The pass of `variant` for `target`, ready to run: the built .spv for
// spirv; for every other target its emitted text compiled by glslang's GLSL
// or HLSL front end. Reflected either way, so the engine binds by name.
Result<ExecutableProgram> load_executable(const Library& library, const LibraryVariant& variant,
                                          PassKind pass, Target target);

// The pass of `variant` for Direct3D `target` from its bytecode (the .d3dbc
// or .dxbc files index.json lists), translated to SPIR-V by `translator`
// and bound by the reflection's registers. Errors: bad_input when the
// library holds no bytecode for the pass (built without an HLSL compiler);
// compile when the translator fails.
Result<ExecutableProgram> load_bytecode_executable(const Library& library,
                                                   const LibraryVariant& variant, PassKind pass,
                                                   Target target,
                                                   const BytecodeTranslator& translator);

// A screen_blur variant's four passes for `target` (Engine::run_screen_blur).
struct ScreenBlurExecutables {
  ExecutableProgram query;
  ExecutableProgram blur_h;
  ExecutableProgram blur_v;
  ExecutableProgram composite;

  ScreenBlurPrograms programs() const {
    return {query.program, blur_h.program, blur_v.program, composite.program};
  }
};

Result<ScreenBlurExecutables> load_screen_blur(const Library& library,
                                               const LibraryVariant& variant, Target target);
// The same, each pass loaded by `load` (load_executable, load_bytecode_executable).
using PassLoader = std::function<Result<ExecutableProgram>(PassKind pass)>;
Result<ScreenBlurExecutables> load_screen_blur(const PassLoader& load);

// The min-max mip of `map` built by `variant`'s minmax_init and
// minmax_reduce passes for `target` (load_executable, Engine::build_minmax).
Result<MinmaxBuild> build_library_minmax(Engine& engine, const Library& library,
                                         const LibraryVariant& variant, Target target,
                                         ShadowMap& map, const ParamBlock& params);

}  // namespace penumbra
