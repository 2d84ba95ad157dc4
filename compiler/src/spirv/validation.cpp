#include "spirv/validation.hpp"

#include <spirv-tools/libspirv.hpp>
#include <string>

namespace penumbra {

Status validate_vulkan_spirv(std::span<const std::uint32_t> spirv) {
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
  std::string messages;
  tools.SetMessageConsumer([&messages](spv_message_level_t, const char*,
                                       const spv_position_t& position, const char* message) {
    messages += "word " + std::to_string(position.index) + ": " + message + "\n";
  });
  if (!tools.Validate(spirv.data(), spirv.size())) {
    return make_error(Error::Kind::compile, "", "spirv-val rejected the module:\n" + messages);
  }
  return {};
}

}  // namespace penumbra
