// `params` is ShadowParams' instance name in the shader source; the member
// names every front end and GL itself report differ only in how they join
// it to the member, so stripping it once gives every target the same key.
#include "penumbra/support/param_block.hpp"

namespace penumbra {

std::string_view param_block_key(std::string_view member_name) {
  constexpr std::string_view instance = "params";
  if (member_name.size() > instance.size() + 1 && member_name.starts_with(instance)) {
    const char separator = member_name[instance.size()];
    if (separator == '.' || separator == '_') return member_name.substr(instance.size() + 1);
  }
  return member_name;
}

}  // namespace penumbra
