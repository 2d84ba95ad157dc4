#include "glsl/spirv_annotations.hpp"
#include "stages/stages.hpp"

namespace penumbra {

Status BannerStage::process(ShaderJob& job) const {
  add_banner_string(job.spirv, job.banner());
  return {};
}

}  // namespace penumbra
