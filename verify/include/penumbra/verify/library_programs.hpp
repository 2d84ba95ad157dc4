// Loading a built library's passes as runnable programs.
#pragma once

#include <functional>
#include <map>
#include <span>
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

// A variant's programs for a list of its passes, by pass.
using LoadedPrograms = std::map<PassKind, ExecutableProgram>;
// How one pass is loaded (load_executable, load_bytecode_executable).
using PassLoader = std::function<Result<ExecutableProgram>(PassKind pass)>;

// Every pass of `passes` loaded by `load`; the first error stops it.
Result<LoadedPrograms> load_passes(std::span<const PassKind> passes, const PassLoader& load);

// `loaded`'s programs for Engine::run_passes; `loaded` must outlive the map.
PassProgramMap program_map(const LoadedPrograms& loaded);

// The min-max mip of `map` built by `variant`'s minmax_init and
// minmax_reduce passes for `target` (load_executable, Engine::build_minmax).
Result<MinmaxBuild> build_library_minmax(Engine& engine, const Library& library,
                                         const LibraryVariant& variant, Target target,
                                         ShadowMap& map, const ParamBlock& params);

}  // namespace penumbra
