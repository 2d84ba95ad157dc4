#include "reflect/reflect_target.hpp"
#include "stages/stages.hpp"

namespace penumbra {

Status ReflectStage::process(ShaderJob& job) const {
  auto iface = reflect(job.spirv);
  if (!iface) return make_error(Error::Kind::compile, job.describe(), iface.error().message);
  job.interface = std::move(*iface);
  auto target = reflect_target(job.target, job.pass, job.variant, job.map_encoding, job.interface);
  if (!target) return make_error(Error::Kind::compile, job.describe(), target.error().message);
  job.reflection = std::move(*target);
  return {};
}

}  // namespace penumbra
