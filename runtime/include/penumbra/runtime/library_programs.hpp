// Loading a built library's passes as runnable programs, and the parameter
// block every pass reads.
#pragma once

#include "penumbra/compiler/library.hpp"
#include "penumbra/reference/light.hpp"
#include "penumbra/runtime/program.hpp"

namespace penumbra {

// Reads the pass's .spv files for `target` and reflects them.
Result<PassProgram> load_program(const Library& library, const LibraryVariant& variant,
                                 PassKind pass, Target target);

// The power of two 2^-k with 2^k >= max_z, so normalized depth z * scale lies
// in [0, 1] and scaling is exact (docs/shader-interface.md).
float depth_scale_for(double max_z);

struct ParamSizes {
  int map_width = 0;
  int map_height = 0;
  int screen_width = 0;
  int screen_height = 0;
};

// ShadowParams for `light`, the map and screen sizes, and a depth scale.
ParamBlock shadow_params(const reference::LightParams& light, const ParamSizes& sizes,
                         float depth_scale);

}  // namespace penumbra
