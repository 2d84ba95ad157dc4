#include "reflect/reflect_target.hpp"
#include "stages/stages.hpp"

namespace penumbra {

Status ReflectStage::process(ShaderJob& job) const {
  // The function form binds what the query pass would, under prefixed
  // names; its harness's input and output are not part of it.
  const bool function = job.form == ShaderForm::function;
  ShaderInterface bound = job.interface;
  if (function) {
    bound.inputs.clear();
    bound.outputs.clear();
  }
  auto target = reflect_target(job.target, job.pass, job.variant, job.map_encoding, bound,
                               function ? kFunctionPrefix : std::string_view());
  if (!target) return make_error(Error::Kind::compile, job.describe(), target.error().message);
  job.reflection = std::move(*target);
  return {};
}

}  // namespace penumbra
