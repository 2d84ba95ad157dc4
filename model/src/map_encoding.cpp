#include "penumbra/model/map_encoding.hpp"

#include "penumbra/model/enum_names.hpp"

namespace penumbra {
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
    case MapEncoding::orthographic:
      return (z - n) / (f - n);
  }
  return z;
}

double decode_depth(MapEncoding encoding, double d, const DepthRange& range) {
  const double n = range.near_plane;
  const double f = range.far_plane;
  switch (encoding) {
    case MapEncoding::linear:
      return d * f;
    // The denominators as weighted sums of the planes, not f - d (f - n):
    // exact at both ends (d = 1 gives f) however far the far plane.
    case MapEncoding::perspective:
      return n * f / ((1.0 - d) * f + d * n);
    case MapEncoding::perspective_reversed:
      return n * f / (d * f + (1.0 - d) * n);
    case MapEncoding::orthographic:
      return (1.0 - d) * n + d * f;
  }
  return d;
}

bool depth_increases(MapEncoding encoding) {
  return encoding != MapEncoding::perspective_reversed;
}

double depth_per_unit(MapEncoding encoding, double z, const DepthRange& range) {
  const double n = range.near_plane;
  const double f = range.far_plane;
  switch (encoding) {
    case MapEncoding::linear:
      return f;
    case MapEncoding::orthographic:
      return f - n;
    // Both perspective encodings are a + b / z with |b| = n f / (f - n).
    case MapEncoding::perspective:
    case MapEncoding::perspective_reversed:
      return z * z * (f - n) / (n * f);
  }
  return f;
}

std::string_view to_string(MapEncoding encoding) {
  switch (encoding) {
    case MapEncoding::linear:
      return "linear";
    case MapEncoding::perspective:
      return "perspective";
    case MapEncoding::perspective_reversed:
      return "perspective_reversed";
    case MapEncoding::orthographic:
      return "orthographic";
  }
  return "linear";
}

std::optional<MapEncoding> parse_map_encoding(std::string_view name) {
  return parse_enum(kAllMapEncodings, name);
}

std::string allowed_map_encodings() {
  return enum_names(kAllMapEncodings);
}

MapEncoding map_encoding(const VariantKeys& keys) {
  return keys.map_encoding ? parse_map_encoding(*keys.map_encoding).value_or(MapEncoding::linear)
                           : MapEncoding::linear;
}

}  // namespace penumbra
