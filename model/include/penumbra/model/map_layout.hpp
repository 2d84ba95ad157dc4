// Where in its texture a variant's shadow map lies (docs/techniques.md,
// "Map layouts"): a texture of its own, one tile of an atlas or one layer
// of a 2D array texture that holds several lights' maps, the tile or layer
// chosen at each call.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "penumbra/model/model.hpp"

namespace penumbra {

enum class MapLayout {
  single,  // the map fills its texture
  atlas,   // one tile of a 2D texture, a rectangle in texture coordinates given per call
  array,   // one layer of a 2D array texture, its index given per call
};

inline constexpr MapLayout kAllMapLayouts[] = {MapLayout::single, MapLayout::atlas,
                                               MapLayout::array};

// "single", "atlas", "array"; and back (none for any other).
std::string_view to_string(MapLayout layout);
std::optional<MapLayout> parse_map_layout(std::string_view name);
// "single, atlas, array", for messages.
std::string allowed_map_layouts();

// The layout a variant reads its map in: its map_layout key, single when
// unset (or not a name parse_map_layout() takes).
MapLayout map_layout(const VariantKeys& keys);

// Why `technique` takes no map_layout, for a manifest's message: the
// min-max techniques' mip would mix an atlas's tiles and an array's layers.
// Empty where it takes one, or has no reason to give.
std::string layouts_refused(Technique technique);

// Why `layout` cannot be read on `target` (array on hlsl_dx9: Direct3D 9 has
// no texture arrays), naming both; empty where it can.
std::string layout_unsupported(MapLayout layout, Target target);

}  // namespace penumbra
