// One pass as a draw block of the Direct3D host's protocol, written from the
// pass's reflection alone: the shaders, the input layout, each stage's
// constants (D3D9 registers with gl_HalfPixel, or D3D10/11 constant-buffer
// members), the pixel shader's textures and samplers.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>

#include "job.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/support/param_block.hpp"

namespace penumbra::d3d {

// Where a draw goes, and what it clears first.
struct DrawTarget {
  std::optional<int> colour;  // a texture id
  int level = 0;
  std::optional<int> depth;  // a depth texture id
  int width = 0;             // of what the draw covers: the half pixel's size
  int height = 0;
  std::optional<std::array<float, 4>> clear_colour;
  std::optional<float> clear_depth;
  bool depth_greater = false;  // the depth test GREATER (a reversed-Z map), else LESS
};

struct DrawGeometry {
  int buffer = 0;      // a vertex buffer id
  unsigned count = 0;  // vertices
};

// A host texture a run provides, and the view format it is read through
// where that is not the reflection's (an engine's D24 or D16 map).
struct BoundTexture {
  int id = 0;
  std::string view_format;
};

// The host textures a run provides, by what the shaders call them.
using PassTextures = std::map<TextureId, BoundTexture>;

// Appends `pass`'s draw to `job`. Errors (bad_input, naming `where`): a
// texture the run does not provide, a parameter missing from `params`, a
// reflection this runtime cannot bind (a register of another dialect).
Status draw_pass(Job& job, const D3dPass& pass, const std::string& where,
                 const PassTextures& textures, const ParamBlock& params, const DrawTarget& target,
                 const DrawGeometry& geometry);

}  // namespace penumbra::d3d
