// How a shadow map stores light-view depth (docs/techniques.md, "Map
// encodings"): today's linear z, or the hardware depth of an engine's
// perspective light projection, forward or reversed-Z, or of an orthographic
// one (a directional light). Every encoding is
// monotonic in z over [near, far], so an encoded comparison decides as the
// linear one does, up to the float32 rounding of the encoding itself.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "penumbra/model/model.hpp"

namespace penumbra {

enum class MapEncoding {
  linear,       // d = z / far: the library's own depth pass (depth_scale = 1 / far)
  perspective,  // d = far (z - near) / (z (far - near)): D3D and Vulkan depth, GL's window z
  perspective_reversed,  // d = near (far - z) / (z (far - near)): reversed-Z, 1 at the near plane
  orthographic,          // d = (z - near) / (far - near): a directional light's box projection
};

inline constexpr MapEncoding kAllMapEncodings[] = {MapEncoding::linear, MapEncoding::perspective,
                                                   MapEncoding::perspective_reversed,
                                                   MapEncoding::orthographic};

// The light projection's clip planes: the map's near plane n (the light's
// near_plane) and its far plane (1 / depth_scale in ShadowParams).
struct DepthRange {
  double near_plane = 9.5;
  double far_plane = 32.0;

  bool operator==(const DepthRange&) const = default;
};

// The value an encoding stores for linear light-view z, and its inverse.
double encode_depth(MapEncoding encoding, double z, const DepthRange& range);
double decode_depth(MapEncoding encoding, double d, const DepthRange& range);

// Whether the stored value grows with z (every encoding but reversed-Z's):
// a texel occludes a receiver where its stored value is below the
// receiver's (above it, reversed).
bool depth_increases(MapEncoding encoding);

// |dz/dd| at linear z: how far in z one unit of the stored value reaches.
double depth_per_unit(MapEncoding encoding, double z, const DepthRange& range);

// Whether the map was drawn by an orthographic projection: its light is
// directional, and every texel's ray is parallel to z.
inline bool is_orthographic(MapEncoding encoding) {
  return encoding == MapEncoding::orthographic;
}

// "linear", "perspective", "perspective_reversed", "orthographic"; and back
// (none for any other).
std::string_view to_string(MapEncoding encoding);
std::optional<MapEncoding> parse_map_encoding(std::string_view name);
// "linear, perspective, perspective_reversed, orthographic", for messages.
std::string allowed_map_encodings();

// The encoding of the map a variant reads: its map_encoding key, linear when
// unset (or not a name parse_map_encoding() takes).
MapEncoding map_encoding(const VariantKeys& keys);

}  // namespace penumbra
