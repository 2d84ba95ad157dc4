#include "targets/rules.hpp"

#include "penumbra/model/target_traits.hpp"

namespace penumbra {

// The module is parsed once here, for whichever target has rules: the
// Direct3D targets, by shader model.
Status check_target_rules(ShaderJob& job) {
  const int model = traits(job.target).shader_model;
  if (model == 0) return {};
  const SpirvModule module(job.spirv);
  if (model == 3) return check_dx9_rules(job, module);
  return check_dx10_rules(job, module);
}

}  // namespace penumbra
