// A test scene made ready on the Vulkan engine for one target: its shadow
// map rendered by that target's own depth pass, read back as linear z for
// the reference. Every backend runs on these: the Vulkan one on the map
// itself, the others on its normalized depth.
#pragma once

#include <map>
#include <optional>
#include <vector>

#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/verify/verify.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra {

// What a depth check holds a map of a scene against: the ray cast at each
// texel's centre, and whether that centre lies clear of every occluder's
// edge. It depends on the scene and the map's size alone, so verify casts
// it once per scene (SceneTruths), whatever target or path drew the map.
struct DepthTruth {
  FloatImage surface;       // 1 channel: the ray cast's linear z at each centre
  std::vector<bool> clear;  // per texel, row 0 first
};

// `scene`'s truth for a `width` x `height` map.
DepthTruth depth_truth(const reference::Scene& scene, int width, int height);

// Where a placed texture holds a map: one of `slots` layers of an array, or
// one of `slots` tiles of an atlas (map_placement.hpp).
struct MapPlacement {
  MapLayout layout = MapLayout::single;
  int slot = 0;   // the map's layer, or its tile
  int slots = 1;  // the array's layers, or the atlas's tiles

  bool operator==(const MapPlacement&) const = default;
};

struct SceneFixture {
  reference::Scene scene;
  ParamBlock params;
  std::shared_ptr<ShadowMap> map;
  // The rendered map as stored: what the target's programs read (the depth
  // image where they compare through shadow_cmp, else the colour image).
  FloatImage normalized_depth;
  FloatImage linear_depth;  // the same, linear z
  // The map's encoding, where the depth pass writes an engine's hardware
  // depth (its reflection's map_encoding); none for linear z.
  std::optional<reference::EncodedDepth> encoded;
  FloatImage receivers;  // (u, v, z_r)
  FloatImage colour;     // what screen_blur's composite draws over (reference::scene_colour)
  DepthCheck depth_check;
  // What a map of the scene is held against (a path that draws its own
  // checks it against the same).
  std::shared_ptr<const DepthTruth> depth_truth;
  // An atlas or array variant's: the texture that holds normalized_depth as
  // one tile or one layer (map_placement.hpp), which the devices read
  // instead of it; `map` and `params` are its.
  std::shared_ptr<const FloatImage> placed;
  MapPlacement placement;  // where `placed` holds the map; single without one

  // What a device uploads as the map: the atlas or array, or the map itself.
  const FloatImage& device_map() const { return placed ? *placed : normalized_depth; }
  // The layout the devices read the map in.
  MapLayout layout() const { return placement.layout; }

  // The depth image the map's readers sample: D32_SFLOAT unless encoded.
  DepthFormat map_format() const { return encoded ? encoded->format : DepthFormat::d32_float; }
  // The map's far plane, 1 / depth_scale in ShadowParams.
  double far_plane() const { return 1.0 / depth_scale_for(scene.far_z); }
};

// Every scene of one target.
struct TargetScenes {
  std::vector<SceneFixture> scenes;
  // Whether the maps hold the min-max mip the target's own passes built, or
  // why they could not; absent until a variant that reads the mip asks.
  std::optional<Status> minmax;
  // The same scenes, each map placed as a map layout reads it
  // (placed_fixture()); each made when a variant of that layout first asks.
  std::map<MapLayout, std::shared_ptr<TargetScenes>> placed;
};

// `linear` (a map of `scene` drawn by `target`'s depth pass, as linear z)
// against a ray cast at each texel's centre: every texel whose centre lies
// clear of an occluder's edge must hold the ray cast's surface, so a map
// shifted by a texel row fails. `backend` is the path that drew it;
// `quantized`, the encoding of a unorm map, whose step widens the tolerance.
DepthCheck check_depth(const reference::Scene& scene, Target target, const FloatImage& linear,
                       const std::string& backend,
                       const std::optional<reference::EncodedDepth>& quantized = {});

// The same against `truth`, `scene`'s depth_truth() for `linear`'s size.
DepthCheck check_depth(const DepthTruth& truth, const reference::Scene& scene, Target target,
                       const FloatImage& linear, const std::string& backend,
                       const std::optional<reference::EncodedDepth>& quantized = {});

class SceneTruths;  // scene_truths.hpp

// `scene` rendered by `depth`, with `receivers` (u, v, z_r per pixel; the
// scene's receivers_width x receivers_height), its depth check against
// `truths`' ray cast. An encoded map is drawn into a `map_format` depth
// image, as an engine's D24 or D16 map, on the targets that compare
// (hlsl_dx9's map is its R32F target); a linear map, the library's own depth
// pass, is always D32_SFLOAT.
Result<SceneFixture> prepare_scene(Engine& engine, SceneTruths& truths, const PassProgram& depth,
                                   Target target, const reference::Scene& scene,
                                   FloatImage receivers,
                                   DepthFormat map_format = DepthFormat::d32_float);

// `stored` (a map in `encoded`'s encoding, or linear z * depth_scale when
// none) as linear z.
FloatImage linear_depth_of(const FloatImage& stored,
                           const std::optional<reference::EncodedDepth>& encoded,
                           float depth_scale);

// The reference of `variant` on `stored` and `linear` (the same map), with
// the fixture's light and receivers: on the stored values where the map is
// encoded (the reference marks the ties), on linear z otherwise.
Result<reference::ReferenceImage> reference_on_map(const Variant& variant,
                                                   const SceneFixture& fixture,
                                                   const FloatImage& stored,
                                                   const FloatImage& linear,
                                                   const reference::SamplingPrecision& precision,
                                                   const reference::ShaderLimits& limits);

}  // namespace penumbra
