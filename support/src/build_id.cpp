#include <link.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "penumbra/support/content_hash.hpp"

namespace penumbra {
namespace {

constexpr std::uint32_t kBuildIdNote = 3;  // NT_GNU_BUILD_ID

// The build ID among one loaded object's PT_NOTE segments.
std::string find_build_id(const dl_phdr_info& info) {
  for (int i = 0; i < info.dlpi_phnum; ++i) {
    const ElfW(Phdr)& segment = info.dlpi_phdr[i];
    if (segment.p_type != PT_NOTE) continue;
    const auto* at = reinterpret_cast<const unsigned char*>(info.dlpi_addr + segment.p_vaddr);
    const unsigned char* end = at + segment.p_memsz;
    while (at + sizeof(ElfW(Nhdr)) <= end) {
      ElfW(Nhdr) note;
      std::memcpy(&note, at, sizeof note);
      const unsigned char* name = at + sizeof note;
      const unsigned char* desc = name + ((note.n_namesz + 3) & ~3u);
      at = desc + ((note.n_descsz + 3) & ~3u);
      if (note.n_type != kBuildIdNote || note.n_namesz != 4 || std::memcmp(name, "GNU", 4) != 0) {
        continue;
      }
      std::string hex;
      for (std::uint32_t b = 0; b < note.n_descsz; ++b) {
        char digits[3];
        std::snprintf(digits, sizeof digits, "%02x", desc[b]);
        hex += digits;
      }
      return hex;
    }
  }
  return {};
}

}  // namespace

std::string executable_build_id() {
  std::string id;
  // The first object dl_iterate_phdr reports is the executable itself.
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* out) {
        *static_cast<std::string*>(out) = find_build_id(*info);
        return 1;
      },
      &id);
  return id;
}

}  // namespace penumbra
