#include "param_block.hpp"

#include <array>
#include <cstring>
#include <string>

namespace penumbra::detail {
namespace {

std::string given_names(const ParamBlock& params) {
  if (params.empty()) return "none";
  std::string names;
  for (const auto& entry : params) names += (names.empty() ? "" : ", ") + entry.first;
  return names;
}

// Direct3D 9 samples pixels at integer coordinates, so its engines shift
// geometry by half a pixel through gl_HalfPixel to match Direct3D 10 and GL.
// Vulkan's rasterizer already samples at pixel centres, as the SPIR-V path
// assumes: no offset makes the Direct3D 9 program rasterize the same pixels.
constexpr std::array<float, 4> kNoHalfPixelOffset{};

}  // namespace

Result<std::vector<std::byte>> pack_params(const PlannedBinding& buffer, const ParamBlock& params,
                                           std::string_view pass) {
  std::vector<std::byte> bytes(buffer.size);
  for (const ConstantFill& constant : buffer.constants) {
    const bool half_pixel = constant.parameter == kHalfPixelParameter;
    std::string name = "'" + constant.name + "'";
    if (constant.parameter != constant.name) name += " (parameter '" + constant.parameter + "')";
    const auto entry = params.find(constant.parameter);
    if (!half_pixel && entry == params.end()) {
      return make_error(
          Error::Kind::bad_input, std::string(pass),
          name + " has no value in the ParamBlock (given: " + given_names(params) + ")");
    }
    const std::array<float, 4>& value = half_pixel ? kNoHalfPixelOffset : entry->second;
    const bool fits = constant.size % sizeof(float) == 0 && constant.size >= sizeof(float) &&
                      constant.size <= sizeof(value) &&
                      constant.offset + constant.size <= buffer.size;
    if (!fits) {
      return make_error(Error::Kind::bad_input, std::string(pass),
                        name + " is " + std::to_string(constant.size) + " bytes at offset " +
                            std::to_string(constant.offset) + " of '" + buffer.name +
                            "'; constants must be float to vec4 inside the buffer");
    }
    std::memcpy(bytes.data() + constant.offset, value.data(), constant.size);
  }
  return bytes;
}

}  // namespace penumbra::detail
