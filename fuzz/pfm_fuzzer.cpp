// libFuzzer target: PFM images (shadow maps and references that verify and
// eval read back).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "penumbra/support/pfm.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  (void)penumbra::parse_pfm(bytes, "fuzz.pfm");
  return 0;
}
