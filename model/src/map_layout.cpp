#include "penumbra/model/map_layout.hpp"

#include "penumbra/model/enum_names.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra {

std::string_view to_string(MapLayout layout) {
  switch (layout) {
    case MapLayout::single:
      return "single";
    case MapLayout::atlas:
      return "atlas";
    case MapLayout::array:
      return "array";
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

std::string layouts_refused(Technique technique) {
  if (!describe(technique).reads_minmax) return {};
  return std::string(to_string(technique)) +
         " reads a min-max mip built over a whole texture: its nodes would mix an atlas's tiles, "
         "and it has no levels per array layer";
}

std::string layout_unsupported(MapLayout layout, Target target) {
  if (layout != MapLayout::array || traits(target).texture_arrays) return {};
  return "map_layout array cannot be read on " + std::string(traits(target).name) +
         " (Direct3D 9 has no texture arrays; map_layout atlas can)";
}

}  // namespace penumbra
