#include "param_block.hpp"

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

}  // namespace

Result<std::vector<std::byte>> pack_params(const ParamsLayout& layout, const ParamBlock& params,
                                           std::string_view pass) {
  std::vector<std::byte> bytes(layout.size);
  for (const BlockMember& member : layout.members) {
    const std::string name = std::string(kParamsBlock) + " member '" + member.name + "'";
    const auto value = params.find(member.name);
    if (value == params.end()) {
      return make_error(
          Error::Kind::bad_input, std::string(pass),
          name + " has no value in the ParamBlock (given: " + given_names(params) + ")");
    }
    const bool fits = member.size % sizeof(float) == 0 && member.size >= sizeof(float) &&
                      member.size <= sizeof(value->second) &&
                      member.offset + member.size <= layout.size;
    if (!fits) {
      return make_error(Error::Kind::bad_input, std::string(pass),
                        name + " is " + std::to_string(member.size) + " bytes at offset " +
                            std::to_string(member.offset) +
                            "; members must be float to vec4 inside the block");
    }
    std::memcpy(bytes.data() + member.offset, value->second.data(), member.size);
  }
  return bytes;
}

}  // namespace penumbra::detail
