#include "penumbra/model/map_encoding.hpp"

#include <array>

namespace penumbra {
namespace {

constexpr std::array kEncodings = {MapEncoding::linear, MapEncoding::perspective,
                                   MapEncoding::perspective_reversed};

}  // namespace

double encode_depth(MapEncoding encoding, double z, const DepthRange& range) {
  const double n = range.near_plane;
  const double f = range.far_plane;
  switch (encoding) {
    case MapEncoding::linear:
      return z / f;
    case MapEncoding::perspective:
      return f * (z - n) / (z * (f - n));
    case MapEncoding::perspective_reversed:
      return n * (f - z) / (z * (f - n));
  }
  return z;
}

double decode_depth(MapEncoding encoding, double d, const DepthRange& range) {
  const double n = range.near_plane;
  const double f = range.far_plane;
  switch (encoding) {
    case MapEncoding::linear:
      return d * f;
    case MapEncoding::perspective:
      return n * f / (f - d * (f - n));
    case MapEncoding::perspective_reversed:
      return n * f / (n + d * (f - n));
  }
  return d;
}

bool depth_increases(MapEncoding encoding) {
  return encoding != MapEncoding::perspective_reversed;
}

double depth_per_unit(MapEncoding encoding, double z, const DepthRange& range) {
  const double n = range.near_plane;
  const double f = range.far_plane;
  // Both perspective encodings are a + b / z with |b| = n f / (f - n).
  return encoding == MapEncoding::linear ? f : z * z * (f - n) / (n * f);
}

std::string_view to_string(MapEncoding encoding) {
  switch (encoding) {
    case MapEncoding::linear:
      return "linear";
    case MapEncoding::perspective:
      return "perspective";
    case MapEncoding::perspective_reversed:
      return "perspective_reversed";
  }
  return "linear";
}

std::optional<MapEncoding> parse_map_encoding(std::string_view name) {
  for (const MapEncoding e : kEncodings) {
    if (to_string(e) == name) return e;
  }
  return std::nullopt;
}

std::string allowed_map_encodings() {
  std::string out;
  for (const MapEncoding e : kEncodings) {
    if (!out.empty()) out += ", ";
    out += to_string(e);
  }
  return out;
}

}  // namespace penumbra
