#include "glsl/spirv_annotations.hpp"

#include <bit>
#include <map>
#include <optional>
#include <set>
#include <spirv/unified1/spirv.hpp>
#include <string>

namespace penumbra {
namespace {

struct Instruction {
  std::size_t offset;  // index of the first word
  spv::Op op;
  std::uint32_t count;
};

std::vector<Instruction> instructions(const std::vector<std::uint32_t>& words) {
  std::vector<Instruction> out;
  for (std::size_t i = 5; i < words.size();) {
    const std::uint32_t count = words[i] >> spv::WordCountShift;
    if (count == 0 || i + count > words.size()) break;
    out.push_back({i, static_cast<spv::Op>(words[i] & spv::OpCodeMask), count});
    i += count;
  }
  return out;
}

// An instruction with `operands` followed by a literal string.
std::vector<std::uint32_t> with_string(spv::Op op, std::vector<std::uint32_t> operands,
                                       const std::string& text) {
  std::vector<std::uint32_t> literal((text.size() + 4) / 4, 0);  // NUL-terminated, padded
  for (std::size_t c = 0; c < text.size(); ++c) {
    literal[c / 4] |= static_cast<std::uint32_t>(static_cast<unsigned char>(text[c]))
                      << (8 * (c % 4));
  }
  std::vector<std::uint32_t> out = {0};
  out.insert(out.end(), operands.begin(), operands.end());
  out.insert(out.end(), literal.begin(), literal.end());
  out[0] = (static_cast<std::uint32_t>(out.size()) << spv::WordCountShift) | op;
  return out;
}

bool same_points(const std::vector<Point2>& a, const std::optional<Disk>& disk) {
  return disk && disk->points == a;
}

}  // namespace

void name_disk_constants(std::vector<std::uint32_t>& spirv, const Variant& variant) {
  if (!variant.blocker_disk && !variant.pcf_disk) return;
  const auto list = instructions(spirv);
  std::set<std::uint32_t> float_types, named;
  std::map<std::uint32_t, float> scalars;
  std::map<std::uint32_t, Point2> pairs;
  std::size_t insert_at = 0;
  std::vector<std::pair<std::uint32_t, std::string>> names;
  for (const Instruction& in : list) {
    const std::uint32_t* w = &spirv[in.offset];
    switch (in.op) {
      case spv::OpName:
        named.insert(w[1]);
        insert_at = in.offset + in.count;
        break;
      case spv::OpTypeFloat:
        if (w[2] == 32) float_types.insert(w[1]);
        break;
      case spv::OpConstant:
        if (float_types.contains(w[1])) scalars[w[2]] = std::bit_cast<float>(w[3]);
        break;
      case spv::OpConstantComposite: {
        const std::uint32_t parts = in.count - 3;
        if (parts == 2 && scalars.contains(w[3]) && scalars.contains(w[4])) {
          pairs[w[2]] = {scalars[w[3]], scalars[w[4]]};
          break;
        }
        std::vector<Point2> points;
        for (std::uint32_t k = 0; k < parts && pairs.contains(w[3 + k]); ++k) {
          points.push_back(pairs[w[3 + k]]);
        }
        if (points.size() != parts || named.contains(w[2])) break;
        const bool blocker = same_points(points, variant.blocker_disk);
        const bool pcf = same_points(points, variant.pcf_disk);
        if (blocker || pcf) {
          names.emplace_back(w[2], blocker && pcf ? "POISSON_DISK"
                                   : blocker      ? "BLOCKER_DISK"
                                                  : "PCF_DISK");
        }
        break;
      }
      default:
        break;
    }
  }
  if (insert_at == 0) return;  // a module without debug names: leave it as is
  std::vector<std::uint32_t> added;
  for (const auto& [id, name] : names) {
    const auto instruction = with_string(spv::OpName, {id}, name);
    added.insert(added.end(), instruction.begin(), instruction.end());
  }
  spirv.insert(spirv.begin() + static_cast<std::ptrdiff_t>(insert_at), added.begin(), added.end());
}

void add_banner_string(std::vector<std::uint32_t>& spirv, const std::string& text) {
  // The debug section starts with OpString / OpSource*, then OpName.
  for (const Instruction& in : instructions(spirv)) {
    switch (in.op) {
      case spv::OpString:
      case spv::OpSourceContinued:
      case spv::OpSource:
      case spv::OpSourceExtension:
      case spv::OpName:
      case spv::OpMemberName: {
        const std::uint32_t id = spirv[3];  // header word 3, the bound: the next free id
        const auto instruction = with_string(spv::OpString, {id}, text);
        spirv[3] = id + 1;
        spirv.insert(spirv.begin() + static_cast<std::ptrdiff_t>(in.offset), instruction.begin(),
                     instruction.end());
        return;
      }
      default:
        break;
    }
  }
}

}  // namespace penumbra
