#include "penumbra/model/map_layout.hpp"

#include "penumbra/model/enum_names.hpp"

namespace penumbra {

std::string_view to_string(MapLayout layout) {
  switch (layout) {
    case MapLayout::single:
      return "single";
    case MapLayout::atlas:
      return "atlas";
  }
  return "single";
}

std::optional<MapLayout> parse_map_layout(std::string_view name) {
  return parse_enum(kAllMapLayouts, name);
}

std::string allowed_map_layouts() {
  return enum_names(kAllMapLayouts);
}

MapLayout map_layout(const VariantKeys& keys) {
  return keys.map_layout ? parse_map_layout(*keys.map_layout).value_or(MapLayout::single)
                         : MapLayout::single;
}

}  // namespace penumbra
