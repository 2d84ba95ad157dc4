#include "targets/sm3_slots.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace penumbra {
namespace {

// Macro instructions that take more than one slot. Everything else,
// texture reads and flow control included, takes one.
constexpr std::array<std::pair<std::string_view, int>, 10> kMacroSlots = {{
    {"crs", 2},
    {"lrp", 2},
    {"m3x2", 2},
    {"m3x3", 3},
    {"m3x4", 4},
    {"m4x3", 3},
    {"m4x4", 4},
    {"nrm", 3},
    {"pow", 3},
    {"sincos", 8},
}};

// Lines that declare or define rather than execute.
bool is_declaration(std::string_view opcode) {
  return opcode.starts_with("vs_") || opcode.starts_with("ps_") || opcode.starts_with("dcl") ||
         opcode == "def" || opcode == "defi" || opcode == "defb";
}

int slots_of(std::string_view opcode) {
  // Modifiers follow the opcode: "texldl_pp", "mov_sat", "if_ne".
  const std::string_view base = opcode.substr(0, opcode.find('_'));
  const auto* macro = std::find_if(kMacroSlots.begin(), kMacroSlots.end(),
                                   [&](const auto& entry) { return entry.first == base; });
  return macro == kMacroSlots.end() ? 1 : macro->second;
}

}  // namespace

int sm3_line_slots(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos) return 0;
  line.remove_prefix(first);
  const std::string_view opcode = line.substr(0, line.find_first_of(" \t\r"));
  if (opcode.starts_with("//") || is_declaration(opcode)) return 0;
  return slots_of(opcode);
}

int count_sm3_slots(std::string_view assembly) {
  int slots = 0;
  while (!assembly.empty()) {
    const std::size_t end = std::min(assembly.find('\n'), assembly.size());
    slots += sm3_line_slots(assembly.substr(0, end));
    assembly.remove_prefix(std::min(end + 1, assembly.size()));
  }
  return slots;
}

}  // namespace penumbra
