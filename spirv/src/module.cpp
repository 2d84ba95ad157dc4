// spirv.hpp's HasResultAndType() tells where each opcode keeps its ids; it is
// compiled only with the utility code enabled, before the first include.
#define SPV_ENABLE_UTILITY_CODE
#include "penumbra/spirv/module.hpp"

#include <algorithm>
#include <cstring>
#include <string_view>

namespace penumbra {

std::uint32_t SpvInstruction::operand(std::size_t i) const {
  const std::size_t at = 1 + (type_id ? 1 : 0) + (result_id ? 1 : 0) + i;
  return at < words.size() ? words[at] : 0;
}

std::size_t SpvInstruction::operand_count() const {
  const std::size_t used = 1 + (type_id ? 1 : 0) + (result_id ? 1 : 0);
  return words.size() > used ? words.size() - used : 0;
}

const SpvBlock* SpvFunction::block(std::uint32_t label) const {
  for (const SpvBlock& b : blocks) {
    if (b.label == label) return &b;
  }
  return nullptr;
}

std::set<std::uint32_t> SpvFunction::loop_construct(const SpvBlock& header) const {
  std::set<std::uint32_t> seen = {header.label};
  std::vector<std::uint32_t> work = {header.label};
  while (!work.empty()) {
    const SpvBlock* b = block(work.back());
    work.pop_back();
    if (!b) continue;
    for (std::uint32_t next : b->successors) {
      if (next != header.merge && seen.insert(next).second) work.push_back(next);
    }
  }
  return seen;
}

SpirvModule::SpirvModule(std::span<const std::uint32_t> words) {
  for (std::size_t i = 5; i < words.size();) {  // skip the 5-word header
    const std::uint32_t count = words[i] >> spv::WordCountShift;
    if (count == 0 || i + count > words.size()) break;  // malformed: spirv-val rejects it
    SpvInstruction in;
    in.op = static_cast<spv::Op>(words[i] & spv::OpCodeMask);
    in.words = words.subspan(i, count);
    bool has_result = false, has_type = false;
    spv::HasResultAndType(in.op, &has_result, &has_type);
    if (has_type && count > 1) in.type_id = in.words[1];
    if (has_result && count > (has_type ? 2u : 1u)) in.result_id = in.words[has_type ? 2 : 1];
    instructions_.push_back(in);
    i += count;
  }
  std::uint32_t bound = 0;  // from the ids themselves, not a header that may lie
  for (const SpvInstruction& in : instructions_) bound = std::max(bound, in.result_id + 1);
  defs_.assign(bound, nullptr);
  SpvFunction* function = nullptr;
  for (std::size_t k = 0; k < instructions_.size(); ++k) {
    const SpvInstruction& in = instructions_[k];
    if (in.result_id && in.result_id < defs_.size()) defs_[in.result_id] = &in;
    switch (in.op) {
      case spv::OpEntryPoint:
        if (!entry_point_) entry_point_ = in.words.size() > 2 ? in.words[2] : 0;
        break;
      case spv::OpExtInstImport: {
        if (in.words.size() < 3) break;
        const auto* text = reinterpret_cast<const char*>(in.words.data() + 2);
        const std::string_view name(text, strnlen(text, (in.words.size() - 2) * 4));
        if (name == "GLSL.std.450") glsl_std_450_ = in.result_id;
        break;
      }
      case spv::OpFunction:
        function = &functions_.emplace_back();
        function->id = in.result_id;
        break;
      case spv::OpLabel:
        if (function) {
          SpvBlock& b = function->blocks.emplace_back();
          b.label = in.result_id;
          b.first = k + 1;
        }
        break;
      case spv::OpSelectionMerge:
        if (function && !function->blocks.empty()) function->blocks.back().merge = in.operand(0);
        break;
      case spv::OpLoopMerge:
        if (function && !function->blocks.empty()) {
          function->blocks.back().merge = in.operand(0);
          function->blocks.back().continue_target = in.operand(1);
        }
        break;
      case spv::OpBranch:
      case spv::OpBranchConditional:
      case spv::OpSwitch:
      case spv::OpReturn:
      case spv::OpReturnValue:
      case spv::OpKill:
      case spv::OpUnreachable:
        if (function && !function->blocks.empty()) {
          SpvBlock& b = function->blocks.back();
          b.end = k + 1;
          if (in.op == spv::OpBranch) b.successors = {in.operand(0)};
          if (in.op == spv::OpBranchConditional) b.successors = {in.operand(1), in.operand(2)};
          if (in.op == spv::OpSwitch) {  // selector, default, then (literal, label) pairs
            b.successors.push_back(in.operand(1));
            for (std::size_t p = 3; p < in.operand_count(); p += 2) {
              b.successors.push_back(in.operand(p));
            }
          }
        }
        break;
      default:
        break;
    }
  }
}

const SpvFunction* SpirvModule::function(std::uint32_t id) const {
  for (const SpvFunction& f : functions_) {
    if (f.id == id) return &f;
  }
  return nullptr;
}

const SpvFunction* SpirvModule::entry_point() const {
  return function(entry_point_);
}

const SpvInstruction* SpirvModule::def(std::uint32_t id) const {
  return id < defs_.size() ? defs_[id] : nullptr;
}

std::optional<std::int64_t> SpirvModule::int_constant(std::uint32_t id) const {
  const SpvInstruction* in = def(id);
  if (!in || in->op != spv::OpConstant) return std::nullopt;
  const SpvInstruction* type = def(in->type_id);
  if (!type || type->op != spv::OpTypeInt || type->operand(0) != 32) return std::nullopt;
  const std::uint32_t value = in->operand(0);
  if (type->operand(1) == 1) return static_cast<std::int32_t>(value);
  return value;
}

bool SpirvModule::is_constant(std::uint32_t id) const {
  const SpvInstruction* in = def(id);
  if (!in) return false;
  switch (in->op) {
    case spv::OpConstant:
    case spv::OpConstantComposite:
    case spv::OpConstantTrue:
    case spv::OpConstantFalse:
    case spv::OpConstantNull:
    case spv::OpSpecConstantOp:
      return true;
    default:
      return false;
  }
}

std::uint32_t SpirvModule::components(std::uint32_t type_id) const {
  const SpvInstruction* type = def(type_id);
  return type && type->op == spv::OpTypeVector ? std::max(type->operand(1), 1u) : 1u;
}

const SpvInstruction* SpirvModule::pointee(std::uint32_t pointer_type_id) const {
  const SpvInstruction* type = def(pointer_type_id);
  return type && type->op == spv::OpTypePointer ? def(type->operand(1)) : nullptr;
}

}  // namespace penumbra
