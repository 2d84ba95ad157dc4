// The depth formats an engine's shadow map may be stored in (docs/techniques.md,
// "Map encodings"): every reflection's d32_float slot also takes a D24 or D16
// depth texture holding a map_encoding's values at that format's precision.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace penumbra {

enum class DepthFormat {
  d32_float,  // D32F: the encoding's float32 value
  d24_unorm,  // D24 (X8_D24, D24S8, DEPTH_COMPONENT24): a multiple of 1 / (2^24 - 1)
  d16_unorm,  // D16: a multiple of 1 / (2^16 - 1)
};

inline constexpr DepthFormat kAllDepthFormats[] = {DepthFormat::d32_float, DepthFormat::d24_unorm,
                                                   DepthFormat::d16_unorm};

// The unorm bits of `format`; 0 for d32_float.
int unorm_bits(DepthFormat format);

// The distance between neighbouring stored values of a unorm format,
// 1 / (2^bits - 1); 0 for d32_float, whose rounding the encodings allow for.
double depth_step(DepthFormat format);

// What a sampler returns for the unorm `code` of a d24_unorm or d16_unorm
// texel: code / (2^bits - 1), rounded to float.
float unorm_depth(DepthFormat format, std::uint32_t code);

// "d32_float", "d24_unorm", "d16_unorm"; and back (none for any other).
std::string_view to_string(DepthFormat format);
std::optional<DepthFormat> parse_depth_format(std::string_view name);
// "d32_float, d24_unorm, d16_unorm", for messages.
std::string allowed_depth_formats();

}  // namespace penumbra
