// libFuzzer target: a library's index.json (load_library's parser), which
// engines, verify, merge and embed read back and which may come from
// another machine's build.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "penumbra/library/library.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  (void)penumbra::parse_library(text, "fuzz-library");
  return 0;
}
