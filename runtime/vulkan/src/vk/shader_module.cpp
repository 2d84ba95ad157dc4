#include "vk/shader_module.hpp"

#include <string>

#include "vk/check.hpp"

namespace penumbra::vk {

Result<ShaderModule> create_shader_module(VkDevice device, std::span<const std::uint32_t> spirv,
                                          std::string_view what) {
  constexpr std::uint32_t kSpirvMagic = 0x07230203;
  // Drivers may crash on garbage rather than fail, so reject non-SPIR-V here.
  if (spirv.size() < 5 || spirv[0] != kSpirvMagic) {
    return make_error(Error::Kind::bad_input, std::string(what),
                      "is not a SPIR-V module (expected the magic number 0x07230203 and a header)");
  }
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule",
                     "creating the " + std::string(what) + " module"));
  return ShaderModule(device, module);
}

}  // namespace penumbra::vk
