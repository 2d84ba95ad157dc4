#include "eval_placement.hpp"

#include <string>

#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/shadow_params.hpp"

namespace penumbra {
namespace {

// The light's rectangle in the given map: x, y, width, height in texels.
std::array<int, 4> light_rect(const EvalInputs& inputs) {
  const FloatImage& map = inputs.shadow_map;
  if (inputs.map_tile) return *inputs.map_tile;
  if (!inputs.map_layer) return {0, 0, map.width, map.height};
  const auto [layer, layers] = *inputs.map_layer;
  const int height = map.height / layers;
  return {0, layer * height, map.width, height};
}

Status check_tile(const EvalInputs& inputs) {
  const auto [x, y, width, height] = *inputs.map_tile;
  const FloatImage& map = inputs.shadow_map;
  if (x >= 0 && y >= 0 && width >= 1 && height >= 1 && x <= map.width - width &&
      y <= map.height - height) {
    return {};
  }
  return make_error(
      Error::Kind::bad_input,
      "--map-tile " + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(width) +
          "," + std::to_string(height),
      "is not inside the " + std::to_string(map.width) + "x" + std::to_string(map.height) +
          " map; allowed: x,y,width,height in texels, x >= 0, y >= 0, width and "
          "height >= 1, x + width <= " +
          std::to_string(map.width) + ", y + height <= " + std::to_string(map.height));
}

Status check_layer(const EvalInputs& inputs) {
  const auto [layer, layers] = *inputs.map_layer;
  const int height = inputs.shadow_map.height;
  if (layers >= 1 && height % layers == 0 && layer >= 0 && layer < layers) return {};
  return make_error(Error::Kind::bad_input,
                    "--map-layer " + std::to_string(layer) + "," + std::to_string(layers),
                    "does not name a layer of the " + std::to_string(height) +
                        " rows of the map; allowed: layer,count with count >= 1 dividing " +
                        std::to_string(height) + " (the layers stacked, layer 0 first) and " +
                        "0 <= layer < count");
}

}  // namespace

Status check_placement(const EvalInputs& inputs) {
  if (inputs.map_tile && inputs.map_layer) {
    return make_error(Error::Kind::bad_input, "--map-layer",
                      "cannot be given with --map-tile; allowed: one of them");
  }
  if (inputs.map_tile) return check_tile(inputs);
  if (inputs.map_layer) return check_layer(inputs);
  return {};
}

Status check_placement_variant(const LibraryVariant& variant, const EvalInputs& inputs) {
  const MapLayout layout = map_layout(variant.variant.keys);
  const std::string reads =
      variant.variant.name + " reads " +
      (layout == MapLayout::single ? std::string("a map of its own (map_layout single)")
                                   : "map_layout " + std::string(to_string(layout)));
  if (inputs.map_tile && layout != MapLayout::atlas) {
    return make_error(Error::Kind::bad_input, "--map-tile",
                      reads + "; allowed only for a variant with map_layout atlas");
  }
  if (inputs.map_layer && layout != MapLayout::array) {
    return make_error(Error::Kind::bad_input, "--map-layer",
                      reads + "; allowed only for a variant with map_layout array");
  }
  return {};
}

FloatImage light_map(const FloatImage& map, const EvalInputs& inputs) {
  if (!inputs.map_tile && !inputs.map_layer) return map;
  const auto [x, y, width, height] = light_rect(inputs);
  FloatImage out(width, height, 1);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) out.at(i, j) = map.at(x + i, y + j);
  }
  return out;
}

FloatImage device_map(FloatImage stored, const LibraryVariant& variant, const EvalInputs& inputs) {
  if (map_layout(variant.variant.keys) == MapLayout::array) {
    stored.layers = inputs.map_layer ? (*inputs.map_layer)[1] : 1;
  }
  return stored;
}

ParamBlock device_params(const EvalInputs& inputs, const FloatImage& receivers, float depth_scale) {
  const auto rect = light_rect(inputs);
  ParamBlock params = shadow_params(
      inputs.light, {rect[2], rect[3], receivers.width, receivers.height}, depth_scale);
  if (inputs.map_tile) {
    place_in_atlas(params, inputs.shadow_map.width, inputs.shadow_map.height, rect);
  }
  if (inputs.map_layer) params["map_layer"] = {float((*inputs.map_layer)[0]), 0.0f, 0.0f, 0.0f};
  return params;
}

reference::SamplingPrecision placement_precision(const EvalInputs& inputs) {
  reference::SamplingPrecision precision;
  if (inputs.map_tile) {
    precision.coordinate_error =
        reference::atlas_coordinate_error(inputs.shadow_map.width, inputs.shadow_map.height);
  }
  return precision;
}

}  // namespace penumbra
