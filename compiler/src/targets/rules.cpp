#include "targets/rules.hpp"

namespace penumbra {

// The module is parsed once here, for whichever target has rules.
Status check_target_rules(ShaderJob& job) {
  if (job.target != Target::hlsl_dx9 && job.target != Target::hlsl_dx10) return {};
  const SpirvModule module(job.spirv);
  if (job.target == Target::hlsl_dx9) return check_dx9_rules(job, module);
  return check_dx10_rules(job, module);
}

}  // namespace penumbra
