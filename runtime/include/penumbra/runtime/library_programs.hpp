// Loading a built library's passes as runnable programs, and the parameter
// block every pass reads.
#pragma once

#include "penumbra/compiler/library.hpp"
#include "penumbra/reference/light.hpp"
#include "penumbra/runtime/engine.hpp"
#include "penumbra/runtime/program.hpp"

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

// The pass of `variant` for `target`, ready to run: the built .spv for
// spirv; for every other target its emitted text compiled by glslang's GLSL
// or HLSL front end. Reflected either way, so the engine binds by name.
Result<ExecutableProgram> load_executable(const Library& library, const LibraryVariant& variant,
                                          PassKind pass, Target target);

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

// The emitted text (or .spv bytes) of one stage of a pass.
Result<std::string> read_pass_file(const Library& library, const LibraryVariant& variant,
                                   PassKind pass, Target target, ShaderStage stage);

// The power of two 2^-k with 2^k >= max_z, so normalized depth z * scale lies
// in [0, 1] and scaling is exact (docs/shader-interface.md).
float depth_scale_for(double max_z);

struct ParamSizes {
  int map_width = 0;
  int map_height = 0;
  int screen_width = 0;
  int screen_height = 0;
};

// ShadowParams for `light`, the map and screen sizes, and a depth scale:
// every member, source_size the map's size and minmax_info.x the map's
// min-max top level (minmax_top_level).
ParamBlock shadow_params(const reference::LightParams& light, const ParamSizes& sizes,
                         float depth_scale);

}  // namespace penumbra
