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

Result<std::vector<std::byte>> pack_params(const ParamsLayout& layout, const ParamBlock& params,
                                           std::string_view pass) {
  std::vector<std::byte> bytes(layout.size);
  for (const BlockMember& member : layout.members) {
    const std::string_view key = param_block_key(member.name);
    std::string name = layout.block + " member '" + member.name + "'";
    if (key != member.name) name += " (ParamBlock key '" + std::string(key) + "')";
    const auto entry = params.find(std::string(key));
    if (key != kHalfPixel && entry == params.end()) {
      return make_error(
          Error::Kind::bad_input, std::string(pass),
          name + " has no value in the ParamBlock (given: " + given_names(params) + ")");
    }
    const std::array<float, 4>& value = key == kHalfPixel ? kNoHalfPixelOffset : entry->second;
    const bool fits = member.size % sizeof(float) == 0 && member.size >= sizeof(float) &&
                      member.size <= sizeof(value) && member.offset + member.size <= layout.size;
    if (!fits) {
      return make_error(Error::Kind::bad_input, std::string(pass),
                        name + " is " + std::to_string(member.size) + " bytes at offset " +
                            std::to_string(member.offset) +
                            "; members must be float to vec4 inside the block");
    }
    std::memcpy(bytes.data() + member.offset, value.data(), member.size);
  }
  return bytes;
}

}  // namespace penumbra::detail
