#include "spirv_inspect.hpp"

#include <cstring>
#include <map>
#include <spirv-tools/libspirv.hpp>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kOpName = 5;
constexpr std::uint32_t kOpTypePointer = 32;
constexpr std::uint32_t kOpVariable = 59;
constexpr std::uint32_t kOpDecorate = 71;
constexpr std::uint32_t kOpMemberDecorate = 72;
constexpr std::uint32_t kDecorationRelaxedPrecision = 0;
constexpr std::uint32_t kDecorationBuiltIn = 11;
constexpr std::uint32_t kDecorationLocation = 30;
constexpr std::uint32_t kDecorationBinding = 33;
constexpr std::uint32_t kDecorationDescriptorSet = 34;
constexpr std::size_t kHeaderWords = 5;

// A nul-terminated literal string packed into the words from `first`.
std::string literal(std::span<const std::uint32_t> words, std::size_t first) {
  std::string out;
  for (std::size_t i = first; i < words.size(); ++i) {
    char bytes[4];
    std::memcpy(bytes, &words[i], 4);
    for (char c : bytes) {
      if (c == '\0') return out;
      out += c;
    }
  }
  return out;
}

// Calls `visit(opcode, operands)` for each instruction after the header.
template <typename Visit>
void for_each_instruction(std::span<const std::uint32_t> spirv, Visit visit) {
  for (std::size_t at = kHeaderWords; at < spirv.size();) {
    const std::uint32_t count = spirv[at] >> 16;
    if (count == 0 || at + count > spirv.size()) return;
    visit(spirv[at] & 0xffffu, spirv.subspan(at + 1, count - 1));
    at += count;
  }
}

}  // namespace

std::string vulkan_validation_errors(std::span<const std::uint32_t> spirv) {
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
  std::string messages;
  tools.SetMessageConsumer(
      [&messages](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        messages += message + std::string("\n");
      });
  if (tools.Validate(spirv.data(), spirv.size())) return {};
  return messages.empty() ? "spirv-val rejected the module\n" : messages;
}

std::vector<SpirvVariable> spirv_variables(std::span<const std::uint32_t> spirv) {
  std::map<std::uint32_t, SpirvVariable> by_id;
  std::map<std::uint32_t, std::uint32_t> pointee;  // pointer type → pointee type
  std::map<std::uint32_t, std::uint32_t> pointer;  // variable → its pointer type
  std::set<std::uint32_t> builtin_blocks;          // structs with BuiltIn members (gl_PerVertex)
  std::vector<std::uint32_t> order;
  for_each_instruction(spirv, [&](std::uint32_t op, std::span<const std::uint32_t> args) {
    if (op == kOpName) by_id[args[0]].name = literal(args, 1);
    if (op == kOpTypePointer) pointee[args[0]] = args[2];
    if (op == kOpVariable) {
      pointer[args[1]] = args[0];
      by_id[args[1]].storage_class = args[2];
      order.push_back(args[1]);
    }
    if (op == kOpMemberDecorate && args.size() >= 3 && args[2] == kDecorationBuiltIn) {
      builtin_blocks.insert(args[0]);
    }
    if (op == kOpDecorate && args.size() >= 2) {
      SpirvVariable& var = by_id[args[0]];
      if (args[1] == kDecorationBuiltIn) var.builtin = true;
      if (args.size() < 3) return;
      if (args[1] == kDecorationLocation) var.location = args[2];
      if (args[1] == kDecorationBinding) var.binding = args[2];
      if (args[1] == kDecorationDescriptorSet) var.set = args[2];
    }
  });
  std::vector<SpirvVariable> out;
  for (std::uint32_t id : order) {
    SpirvVariable var = by_id[id];
    var.builtin = var.builtin || builtin_blocks.contains(pointee[pointer[id]]);
    out.push_back(std::move(var));
  }
  return out;
}

std::set<std::uint32_t> spirv_builtins(std::span<const std::uint32_t> spirv) {
  std::set<std::uint32_t> out;
  for_each_instruction(spirv, [&](std::uint32_t op, std::span<const std::uint32_t> args) {
    if (op == kOpDecorate && args.size() >= 3 && args[1] == kDecorationBuiltIn) out.insert(args[2]);
    if (op == kOpMemberDecorate && args.size() >= 4 && args[2] == kDecorationBuiltIn) {
      out.insert(args[3]);
    }
  });
  return out;
}

bool has_relaxed_precision(std::span<const std::uint32_t> spirv) {
  bool found = false;
  for_each_instruction(spirv, [&](std::uint32_t op, std::span<const std::uint32_t> args) {
    found =
        found || (op == kOpDecorate && args.size() >= 2 && args[1] == kDecorationRelaxedPrecision);
    found = found ||
            (op == kOpMemberDecorate && args.size() >= 3 && args[2] == kDecorationRelaxedPrecision);
  });
  return found;
}

}  // namespace penumbra::testing
