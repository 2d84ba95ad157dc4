#include "penumbra/compiler/stage.hpp"

namespace penumbra {

std::string_view to_string(PassKind pass) {
  return pass == PassKind::depth ? "depth" : "query";
}

std::string_view to_string(ShaderStage stage) {
  return stage == ShaderStage::vertex ? "vertex" : "fragment";
}

std::string ShaderJob::describe() const {
  std::string out = variant ? "variant " + variant->name : std::string("shared pass");
  out += ", target " + std::string(to_string(target)) + ", " + source_path;
  return out;
}

}  // namespace penumbra
