#include "penumbra/spirv/reflection.hpp"
#include "stages/stages.hpp"

namespace penumbra {

Status InterfaceStage::process(ShaderJob& job) const {
  auto iface = reflect(job.spirv);
  if (!iface) return make_error(Error::Kind::compile, job.describe(), iface.error().message);
  job.interface = std::move(*iface);
  return {};
}

}  // namespace penumbra
