#include "spirv/validation.hpp"
#include "stages/stages.hpp"

namespace penumbra {

Status ValidateStage::process(ShaderJob& job) const {
  // The shared wrapper reports no location; the job names the variant and target.
  if (auto valid = validate_vulkan_spirv(job.spirv); !valid) {
    return make_error(valid.error().kind, job.describe(), valid.error().message);
  }
  return {};
}

}  // namespace penumbra
