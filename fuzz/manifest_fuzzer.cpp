// libFuzzer target: permutation manifests (parse_manifest, then expand), the
// first thing a build step reads from its user. Any input must end in a
// manifest or an error, within libFuzzer's memory and time limits.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "penumbra/compiler/manifest.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto manifest = penumbra::parse_manifest(text, "fuzz.json");
  if (manifest) (void)penumbra::expand(*manifest);
  return 0;
}
