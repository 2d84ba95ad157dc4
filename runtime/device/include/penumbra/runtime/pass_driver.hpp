// The pass driver: runs a pass list (a technique's, TechniqueDescription::
// passes, or any other) on a Device, the same way on every API. Each pass
// reads what the model says it reads (PassDescription::reads):
//
//   depth          the casters into the shadow map
//   minmax_init    the map into min-max level 1
//   minmax_reduce  level l - 1 into level l, up to the 1x1 level N; the
//                  levels are then gathered into the map's min-max mip
//   query          the map (and its mip) at the receivers, into a screen
//   deferred       the same at the camera's depth, in the query's place
//   blur_h, ...    every later full-screen pass reads the previous one's
//                  target as screen_factor (and the receivers, the scene
//                  colour where it reads them)
//
// A new pass shape changes the model's description and this driver; the
// devices only draw.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "penumbra/model/shader_contract.hpp"
#include "penumbra/runtime/device.hpp"

namespace penumbra::runtime {

// The programs of a variant's passes, loaded on one device.
using PassPrograms = std::map<PassKind, Program>;

// What the passes start from; each pass takes what it reads.
struct PassInputs {
  // The shadow map: drawn by the list's depth pass, else this one.
  std::optional<Texture> map;
  // Its min-max mip, for a list without the min-max passes that reads it.
  std::optional<Texture> mip;
  // The depth pass: the casters (light-view xyz, a triangle list) and the
  // map's size and depth format.
  std::span<const std::array<float, 3>> casters;
  int map_width = 0;
  int map_height = 0;
  DepthFormat depth_format = DepthFormat::d32_float;
  std::optional<Texture> receivers;     // the query's screen, and the blur passes'
  std::optional<Texture> camera_depth;  // the deferred pass's screen
  std::optional<Texture> scene_colour;  // what the composite darkens
  // Every pass's ShadowParams. The driver sets the size members a pass
  // reads its target's size from: screen_size (each full-screen pass's
  // target), and source_size (the level a min-max pass reads).
  ParamBlock params;
};

// What the passes made, each a Texture the caller releases (release_all).
struct PassResults {
  std::optional<Texture> map;                         // drawn, or the input's
  std::optional<Texture> mip;                         // gathered, or the input's
  std::vector<Texture> levels;                        // min-max levels 1..N, drawn
  std::vector<std::pair<PassKind, Texture>> screens;  // each screen pass's target, in order
  std::optional<double> gpu_ms;                       // the draws' GPU time summed, when timed

  // `pass`'s screen target; none when it did not run.
  std::optional<Texture> screen(PassKind pass) const;
};

// The host images a pass list's screen passes read besides the map; each
// must outlive the call that takes it.
struct ScreenImages {
  const FloatImage* receivers = nullptr;     // the query's screen (u, v, z_r), 3 or 4 channels
  const FloatImage* camera_depth = nullptr;  // the deferred pass's screen, one channel
  const FloatImage* scene_colour = nullptr;  // what the composite darkens, RGBA
};

// What a pass list drew, read back: each screen pass's target, every
// channel, in the order the passes ran.
struct PassOutputs {
  std::vector<std::pair<PassKind, FloatImage>> targets;
  std::optional<double> gpu_ms;  // the draws' GPU time summed, when timed

  // `pass`'s target; nullptr when it did not run.
  const FloatImage* target(PassKind pass) const;
};

// Runs `passes` in order, each with its program from `programs`. Errors:
// bad_input naming the pass for one without a program, or without what it
// reads (a map, a screen, the level below); the device's.
Result<PassResults> run_passes(Device& device, std::span<const PassKind> passes,
                               const PassPrograms& programs, const PassInputs& inputs);

// Those of `images` some pass of `passes` reads, uploaded as `inputs`'
// receivers, camera depth and scene colour.
Status upload_screen(Device& device, const ScreenImages& images, std::span<const PassKind> passes,
                     PassInputs& inputs);

// run_passes(), then every screen pass's target read back in one read_all().
Result<PassOutputs> run_and_read(Device& device, std::span<const PassKind> passes,
                                 const PassPrograms& programs, const PassInputs& inputs);

// The depth pass alone: `casters` (light-view xyz, a triangle list) drawn
// by `depth` into a new width x height map of `format`.
Result<Texture> draw_map(Device& device, Program depth,
                         std::span<const std::array<float, 3>> casters, int width, int height,
                         DepthFormat format, const ParamBlock& params);

// An engine's own program around a function form (docs/function-form.md):
// `triangles` drawn into a width x height target with a depth buffer,
// offered the map as the function form's textures and its mip where given.
Result<Drawn> draw_surface(Device& device, Program program,
                           std::span<const std::array<float, 3>> triangles, int width, int height,
                           Texture map, std::optional<Texture> mip, const ParamBlock& params);

// Errors (bad_input, `where`): `vertices` is no whole number of triangles.
// The driver checks every triangle list it draws; an engine checks its
// caller's before it prepares anything.
Status check_triangle_list(std::span<const std::array<float, 3>> vertices, std::string_view where);

// Which of a technique's passes run, for an engine that draws its own map
// or takes one (`draw_depth`), and shades receivers or its camera's depth
// (`deferred`): the deferred pass in the query's place, or not at all.
std::vector<PassKind> select_passes(std::span<const PassKind> technique_passes, bool draw_depth,
                                    bool deferred);

// Releases what `results` drew (not the inputs it was given).
void release_all(Device& device, const PassResults& results, const PassInputs& inputs);

}  // namespace penumbra::runtime
