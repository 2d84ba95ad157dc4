#include "spirv/descriptor_sets.hpp"

#include <spirv/unified1/spirv.hpp>

namespace penumbra {

void move_to_descriptor_set(std::vector<std::uint32_t>& spirv, std::uint32_t set) {
  constexpr std::size_t kHeaderWords = 5;
  for (std::size_t i = kHeaderWords; i < spirv.size();) {
    const std::uint32_t count = spirv[i] >> spv::WordCountShift;
    if (count == 0 || i + count > spirv.size()) return;  // malformed: left to the validator
    const bool decorates_set = (spirv[i] & spv::OpCodeMask) == spv::OpDecorate && count == 4 &&
                               spirv[i + 2] == spv::DecorationDescriptorSet;
    if (decorates_set) spirv[i + 3] = set;
    i += count;
  }
}

}  // namespace penumbra
