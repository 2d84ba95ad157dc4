#include "glsl/spirv_annotations.hpp"

#include <bit>
#include <map>
#include <optional>
#include <set>
#include <spirv/unified1/spirv.hpp>
#include <string>

#include "penumbra/spirv/module.hpp"

namespace penumbra {
namespace {

// Index of an instruction's first word in `spirv`, the words `module` views.
std::size_t offset_of(const SpvInstruction& in, const std::vector<std::uint32_t>& spirv) {
  return static_cast<std::size_t>(in.words.data() - spirv.data());
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

// Index of the first word of the debug section, which starts with OpString /
// OpSource*, then OpName; nullopt for a module without one.
std::optional<std::size_t> debug_section_start(const std::vector<std::uint32_t>& spirv) {
  const SpirvModule module(spirv);
  for (const SpvInstruction& in : module.instructions()) {
    switch (in.op) {
      case spv::OpString:
      case spv::OpSourceContinued:
      case spv::OpSource:
      case spv::OpSourceExtension:
      case spv::OpName:
      case spv::OpMemberName:
        return offset_of(in, spirv);
      default:
        break;
    }
  }
  return std::nullopt;
}

bool same_points(const std::vector<Point2>& a, const std::optional<Disk>& disk) {
  return disk && disk->points == a;
}

// Whether the constant composite holds exactly the float constants `values`.
bool same_scalars(const SpvInstruction& composite, const std::map<std::uint32_t, float>& scalars,
                  const std::vector<float>& values) {
  if (values.empty() || composite.operand_count() != values.size()) return false;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const auto found = scalars.find(composite.operand(k));
    if (found == scalars.end() || found->second != values[k]) return false;
  }
  return true;
}

// The OpNames to add and where: after the last OpName (0: there is none).
struct ConstantNames {
  std::size_t insert_at = 0;
  std::vector<std::pair<std::uint32_t, std::string>> names;
};

// Reads the module without changing it: the view borrows the words, so all
// reading is done before name_baked_constants inserts.
ConstantNames find_constant_names(const std::vector<std::uint32_t>& spirv, const Variant& variant) {
  const SpirvModule module(spirv);
  std::set<std::uint32_t> float_types, named;
  std::map<std::uint32_t, float> scalars;
  std::map<std::uint32_t, Point2> pairs;
  ConstantNames found;
  for (const SpvInstruction& in : module.instructions()) {
    switch (in.op) {
      case spv::OpName:
        named.insert(in.operand(0));
        found.insert_at = offset_of(in, spirv) + in.words.size();
        break;
      case spv::OpTypeFloat:
        if (in.operand(0) == 32) float_types.insert(in.result_id);
        break;
      case spv::OpConstant:
        if (float_types.contains(in.type_id)) {
          scalars[in.result_id] = std::bit_cast<float>(in.operand(0));
        }
        break;
      case spv::OpConstantComposite: {
        const std::size_t parts = in.operand_count();
        if (!named.contains(in.result_id) && same_scalars(in, scalars, variant.blur_weights)) {
          found.names.emplace_back(in.result_id, "BLUR_WEIGHTS");
          break;
        }
        if (parts == 2 && scalars.contains(in.operand(0)) && scalars.contains(in.operand(1))) {
          pairs[in.result_id] = {scalars[in.operand(0)], scalars[in.operand(1)]};
          break;
        }
        std::vector<Point2> points;
        for (std::size_t k = 0; k < parts && pairs.contains(in.operand(k)); ++k) {
          points.push_back(pairs[in.operand(k)]);
        }
        if (points.size() != parts || named.contains(in.result_id)) break;
        const bool blocker = same_points(points, variant.blocker_disk);
        const bool pcf = same_points(points, variant.pcf_disk);
        if (blocker || pcf) {
          found.names.emplace_back(in.result_id, blocker && pcf ? "POISSON_DISK"
                                                 : blocker      ? "BLOCKER_DISK"
                                                                : "PCF_DISK");
        }
        break;
      }
      default:
        break;
    }
  }
  return found;
}

// The literal string that starts at operand `first` of `in`.
std::string literal_string(const SpvInstruction& in, std::size_t first) {
  std::string out;
  for (std::size_t k = first; k < in.operand_count(); ++k) {
    for (int byte = 0; byte < 4; ++byte) {
      const char c = static_cast<char>((in.operand(k) >> (8 * byte)) & 0xffu);
      if (c == '\0') return out;
      out += c;
    }
  }
  return out;
}

// Whether `id` names something at module scope that the text declares.
bool module_scope(const SpirvModule& module, std::uint32_t id) {
  const SpvInstruction* def = module.def(id);
  if (!def) return false;
  switch (def->op) {
    case spv::OpFunction:
      return !module.entry_point() || module.entry_point()->id != id;
    case spv::OpVariable:
      return def->operand(0) != spv::StorageClassFunction;
    case spv::OpTypeStruct:
    case spv::OpConstant:
    case spv::OpConstantComposite:
    case spv::OpSpecConstant:
    case spv::OpSpecConstantComposite:
      return true;
    default:
      return false;
  }
}

}  // namespace

void prefix_global_names(std::vector<std::uint32_t>& spirv, const std::string& prefix) {
  std::vector<std::uint32_t> out;
  out.reserve(spirv.size() + 64);
  {
    const SpirvModule module(spirv);
    const auto words = module.instructions();
    out.assign(spirv.begin(),
               spirv.begin() + static_cast<std::ptrdiff_t>(
                                   words.empty() ? spirv.size() : offset_of(words.front(), spirv)));
    for (const SpvInstruction& in : words) {
      const std::string name = in.op == spv::OpName ? literal_string(in, 1) : "";
      if (in.op == spv::OpName && module_scope(module, in.operand(0)) &&
          !name.starts_with(prefix) && !name.starts_with("gl_")) {
        const auto renamed = with_string(spv::OpName, {in.operand(0)}, prefix + name);
        out.insert(out.end(), renamed.begin(), renamed.end());
      } else {
        out.insert(out.end(), in.words.begin(), in.words.end());
      }
    }
  }
  spirv = std::move(out);
}

void name_baked_constants(std::vector<std::uint32_t>& spirv, const Variant& variant) {
  if (!variant.blocker_disk && !variant.pcf_disk && variant.blur_weights.empty()) return;
  const auto [insert_at, names] = find_constant_names(spirv, variant);
  if (insert_at == 0) return;  // a module without debug names: leave it as is
  std::vector<std::uint32_t> added;
  for (const auto& [id, name] : names) {
    const auto instruction = with_string(spv::OpName, {id}, name);
    added.insert(added.end(), instruction.begin(), instruction.end());
  }
  spirv.insert(spirv.begin() + static_cast<std::ptrdiff_t>(insert_at), added.begin(), added.end());
}

void add_banner_string(std::vector<std::uint32_t>& spirv, const std::string& text) {
  const auto insert_at = debug_section_start(spirv);
  if (!insert_at) return;
  const std::uint32_t id = spirv[3];  // header word 3, the bound: the next free id
  const auto instruction = with_string(spv::OpString, {id}, text);
  spirv[3] = id + 1;
  spirv.insert(spirv.begin() + static_cast<std::ptrdiff_t>(*insert_at), instruction.begin(),
               instruction.end());
}

}  // namespace penumbra
