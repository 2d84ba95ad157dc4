// A read-only view of a SPIR-V module for the target rules and the debug
// annotations: instructions with their result ids, definitions by id, and
// each function's blocks with their structured-control-flow merges. It
// borrows the words it is given.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <spirv/unified1/spirv.hpp>
#include <vector>

namespace penumbra {

struct SpvInstruction {
  spv::Op op = spv::OpNop;
  std::span<const std::uint32_t> words;  // words[0] is the opcode word
  std::uint32_t type_id = 0;             // 0: no result type
  std::uint32_t result_id = 0;           // 0: no result
  // Word `i` after the result id (or after the opcode word when there is none).
  std::uint32_t operand(std::size_t i) const;
  std::size_t operand_count() const;
};

struct SpvBlock {
  std::uint32_t label = 0;
  std::size_t first = 0;              // index of the first instruction after OpLabel
  std::size_t end = 0;                // one past the terminator
  std::uint32_t merge = 0;            // OpSelectionMerge / OpLoopMerge target; 0: none
  std::uint32_t continue_target = 0;  // loop headers only
  std::vector<std::uint32_t> successors;
  bool is_loop_header() const { return continue_target != 0; }
};

struct SpvFunction {
  std::uint32_t id = 0;
  std::vector<SpvBlock> blocks;  // in module order; blocks[0] is the entry
  const SpvBlock* block(std::uint32_t label) const;
  // Labels of the loop construct headed by `header`: the blocks reachable
  // from it without passing its merge block (continue construct included).
  std::set<std::uint32_t> loop_construct(const SpvBlock& header) const;
};

class SpirvModule {
 public:
  explicit SpirvModule(std::span<const std::uint32_t> words);
  SpirvModule(const SpirvModule&) = delete;  // defs_ points into instructions_
  SpirvModule& operator=(const SpirvModule&) = delete;

  std::span<const SpvInstruction> instructions() const { return instructions_; }
  const std::vector<SpvFunction>& functions() const { return functions_; }
  const SpvFunction* function(std::uint32_t id) const;
  // The function of the module's first OpEntryPoint; null when there is none.
  const SpvFunction* entry_point() const;

  const SpvInstruction* def(std::uint32_t id) const;
  // The value of a 32-bit integer OpConstant; nullopt for anything else.
  std::optional<std::int64_t> int_constant(std::uint32_t id) const;
  bool is_constant(std::uint32_t id) const;
  // Vector width of a type (1 for scalars and everything else).
  std::uint32_t components(std::uint32_t type_id) const;
  // The type an OpTypePointer points to; null for anything else.
  const SpvInstruction* pointee(std::uint32_t pointer_type_id) const;
  // The id of the GLSL.std.450 OpExtInstImport; 0 when not imported.
  std::uint32_t glsl_std_450() const { return glsl_std_450_; }

 private:
  std::vector<SpvInstruction> instructions_;
  std::vector<const SpvInstruction*> defs_;  // by result id
  std::vector<SpvFunction> functions_;
  std::uint32_t entry_point_ = 0;
  std::uint32_t glsl_std_450_ = 0;
};

}  // namespace penumbra
