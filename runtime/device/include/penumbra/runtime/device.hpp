// Device: what the pass driver (pass_driver.hpp) asks of a graphics API.
// Vulkan, OpenGL and Direct3D each implement it once (runtime/vulkan,
// runtime/gl, runtime/d3d). It speaks of the model's passes and textures
// only, never of a technique: the pass list says what runs.
//
// Lifecycle: an API's runtime opens the device and loads programs with its
// own loader (SPIR-V, GLSL text or Direct3D bytecode, each bound by its
// reflection), which hands out Programs. Then, from one thread at a time,
// any number of upload / draw / gather_mip / read / release calls. A device
// may defer work until read(), which then also returns the errors of the
// draws it ran. A Texture lives until release() or the device's end.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/pass.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::runtime {

// A program the device loaded: a pass's two stages and their reflection.
struct Program {
  int id = 0;
  bool operator==(const Program&) const = default;
};

// A texture the device holds: an uploaded image, a draw's target or a mip.
struct Texture {
  int id = 0;
  int width = 0;
  int height = 0;
  bool operator==(const Texture&) const = default;
};

// `texture` offered to a draw as the model's texture `as`. The device binds
// each texture the program's reflection reads from the offer of its id
// (the constant disks it fills itself) and fails, bad_input naming the
// draw, where no offer supplies one.
struct Offer {
  TextureId as;
  Texture texture;
  bool operator==(const Offer&) const = default;
};

// One draw into a new target of its own, cleared first.
struct Draw {
  // The pass: its target's format is describe(pass).output's, and a depth
  // pass's target is a shadow map. None for an engine's own program around
  // a function form, whose reflection names its target's format.
  std::optional<PassKind> pass;
  Program program;
  std::string where;  // names the draw in errors: "blur_h pass", "surface pass"
  std::vector<Offer> inputs;
  ParamBlock params;  // every member the program's blocks declare
  int width = 0;      // the target's size
  int height = 0;
  // Empty: one full-screen triangle (support/full_screen_triangle.hpp), no
  // depth buffer. Otherwise a triangle list at the program's vertex input,
  // no culling, with a depth buffer cleared to 1.0 and tested LESS (a
  // reversed-Z depth program, by its reflection: cleared to 0, GREATER).
  std::span<const std::array<float, 3>> triangles;
  DepthFormat depth_format = DepthFormat::d32_float;  // a depth pass's map
};

// What a draw made: its target, and its GPU time where the device times
// draws as they run (absent otherwise).
struct Drawn {
  Texture target;
  std::optional<double> gpu_ms;
};

class Device {
 public:
  virtual ~Device() = default;

  // `image` (row 0 first) on the device, to be offered as `as`: the map's
  // normalized depth (shadow_depth, one channel, values in [0, 1]), the
  // receivers (3 or 4 channels), the camera's depth (one channel) or the
  // scene colour (4 channels). Errors: bad_input for an image the texture
  // cannot hold; device.
  virtual Result<Texture> upload(TextureId as, const FloatImage& image) = 0;

  // Runs `draw`. Errors: bad_input (an offer missing, a program that
  // disagrees with its target), device.
  virtual Result<Drawn> draw(const Draw& draw) = 0;

  // The min-max mip of `map`, offered as shadow_minmax: `levels` (1..N, each
  // a min-max pass's target, support/minmax_levels.hpp's sizes) copied into
  // one mip chain, its padding 1.0.
  virtual Result<Texture> gather_mip(Texture map, std::span<const Texture> levels) = 0;

  // Every channel of each of `textures` (a map: its normalized depth), row
  // 0 first. A device that defers its work runs it once for all of them.
  virtual Result<std::vector<FloatImage>> read_all(std::span<const Texture> textures) = 0;
  // read_all() of one texture.
  Result<FloatImage> read(Texture texture);

  // Frees `texture` once the work that reads it is done.
  virtual void release(Texture texture) = 0;
};

}  // namespace penumbra::runtime
