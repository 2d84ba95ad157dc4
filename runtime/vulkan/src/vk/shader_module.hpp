// ShaderModule: one SPIR-V module.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>

#include "penumbra/support/result.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

using ShaderModule = DeviceObject<VkShaderModule, vkDestroyShaderModule>;

// `what` names the stage in error messages ("query pass vertex shader").
// Words that do not start with the SPIR-V magic number are a bad_input Error.
Result<ShaderModule> create_shader_module(VkDevice device, std::span<const std::uint32_t> spirv,
                                          std::string_view what);

}  // namespace penumbra::vk
