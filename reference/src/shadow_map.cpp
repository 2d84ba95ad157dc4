#include "penumbra/reference/shadow_map.hpp"

namespace penumbra::reference {

double tie_margin(const EncodedDepth& encoded, double z) {
  constexpr double kStoredReach = 0x1p-20;    // 16 ulp of 1
  constexpr double kReceiverReach = 0x1p-22;  // 4 ulp of z
  const double stored_reach = kStoredReach + depth_step(encoded.format);
  return stored_reach * depth_per_unit(encoded.encoding, z, encoded.range) + kReceiverReach * z;
}

}  // namespace penumbra::reference
