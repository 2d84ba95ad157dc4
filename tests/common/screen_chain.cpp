#include "screen_chain.hpp"

#include <string>

#include "penumbra/support/image_checks.hpp"

namespace penumbra::testing {

Result<ScreenChain> screen_chain(const runtime::PassOutputs& outputs) {
  for (PassKind pass : {PassKind::query, PassKind::blur_h, PassKind::blur_v, PassKind::composite}) {
    if (outputs.target(pass) == nullptr) {
      return make_error(Error::Kind::internal, std::string(to_string(pass)),
                        "the pass did not run");
    }
  }
  const FloatImage& query = *outputs.target(PassKind::query);
  return ScreenChain{
      channel(query, 0), channel(query, 1), channel(*outputs.target(PassKind::blur_h), 0),
      channel(*outputs.target(PassKind::blur_v), 0), *outputs.target(PassKind::composite)};
}

}  // namespace penumbra::testing
