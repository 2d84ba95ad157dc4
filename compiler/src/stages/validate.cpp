#include <spirv-tools/libspirv.hpp>

#include "stages/stages.hpp"

namespace penumbra {

Status ValidateStage::process(ShaderJob& job) const {
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
  std::string messages;
  tools.SetMessageConsumer([&messages](spv_message_level_t, const char*,
                                       const spv_position_t& position, const char* message) {
    messages += "word " + std::to_string(position.index) + ": " + message + "\n";
  });
  if (!tools.Validate(job.spirv)) {
    return make_error(Error::Kind::compile, job.describe(),
                      "spirv-val rejected the module:\n" + messages);
  }
  return {};
}

}  // namespace penumbra
