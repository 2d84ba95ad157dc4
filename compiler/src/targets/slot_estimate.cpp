#include "targets/slot_estimate.hpp"

#include <map>
#include <optional>

#include "targets/ps30_costs.hpp"

namespace penumbra {
namespace {

using Labels = std::set<std::uint32_t>;

// `a <op> b` for the integer comparisons a counted loop tests; nullopt for other ops.
std::optional<bool> compare(spv::Op op, std::int64_t a, std::int64_t b) {
  switch (op) {
    case spv::OpSLessThan:
    case spv::OpULessThan:
      return a < b;
    case spv::OpSLessThanEqual:
    case spv::OpULessThanEqual:
      return a <= b;
    case spv::OpSGreaterThan:
    case spv::OpUGreaterThan:
      return a > b;
    case spv::OpSGreaterThanEqual:
    case spv::OpUGreaterThanEqual:
      return a >= b;
    case spv::OpINotEqual:
      return a != b;
    default:
      return std::nullopt;
  }
}

// Walks structured control flow the way FXC lays a shader out: every call
// inlined, both arms of a branch present, loops rolled or unrolled.
class Estimator {
 public:
  explicit Estimator(const SpirvModule& module) : m_(module) {
    std::map<std::uint32_t, int> uses;
    for (const SpvInstruction& in : m_.instructions()) {
      for (std::size_t k = 0; k < in.operand_count(); ++k) ++uses[in.operand(k)];
    }
    // FXC folds a multiply whose only use is an add into one mad.
    for (const SpvInstruction& in : m_.instructions()) {
      if (in.op != spv::OpFAdd && in.op != spv::OpFSub) continue;
      for (std::size_t k = 0; k < 2; ++k) {
        const SpvInstruction* def = m_.def(in.operand(k));
        if (def && (def->op == spv::OpFMul || def->op == spv::OpVectorTimesScalar) &&
            uses[def->result_id] == 1) {
          fused_.insert(def->result_id);
          break;
        }
      }
    }
  }

  int function(std::uint32_t id) {
    if (auto it = function_slots_.find(id); it != function_slots_.end()) return it->second;
    function_slots_[id] = 0;  // SPIR-V has no recursion; this only guards bad input
    const SpvFunction* f = m_.function(id);
    const int slots = f && !f->blocks.empty() ? region(*f, f->blocks[0].label, {}) : 0;
    return function_slots_[id] = slots;
  }

 private:
  int block(const SpvBlock& b) {
    int slots = 0;
    for (std::size_t k = b.first; k < b.end; ++k) {
      const SpvInstruction& in = m_.instructions()[k];
      if (in.op == spv::OpFunctionCall) {
        slots += function(in.operand(0));
      } else if (!fused_.contains(in.result_id)) {
        slots += ps30_instruction_slots(m_, in);
      }
    }
    return slots;
  }

  // Slots from `start` to the first of `stops` (or a return).
  int region(const SpvFunction& f, std::uint32_t start, const Labels& stops) {
    int slots = 0;
    Labels visited;
    for (std::uint32_t label = start;
         label != 0 && !stops.contains(label) && visited.insert(label).second;) {
      const SpvBlock* b = f.block(label);
      if (!b) break;
      if (b->is_loop_header()) {
        slots += loop(f, *b);
        label = b->merge;
        continue;
      }
      slots += block(*b);
      if (b->merge != 0) {  // if/else (or switch): both arms are in the program
        Labels inner = stops, arms;
        inner.insert(b->merge);
        for (std::uint32_t arm : b->successors) {
          if (arm != b->merge && arms.insert(arm).second) slots += region(f, arm, inner);
        }
        slots += kPs30IfSlots + kPs30EndifSlots + (arms.size() > 1 ? kPs30ElseSlots : 0);
        label = b->merge;
        continue;
      }
      if (b->successors.size() > 1) slots += kPs30BreakSlots;  // a conditional break
      label = 0;
      for (std::uint32_t next : b->successors) {
        if (!stops.contains(next)) {
          label = next;
          break;
        }
      }
    }
    return slots;
  }

  int loop(const SpvFunction& f, const SpvBlock& header) {
    const Labels construct = f.loop_construct(header);
    const Labels stops = {header.merge, header.continue_target};
    // glslang's `for`: the header branches to a test that exits to the merge.
    const SpvBlock* test = &header;
    if (header.successors.size() == 1) test = f.block(header.successors[0]);
    const bool counted = test && test->successors.size() == 2 &&
                         test->successors[1] == header.merge &&
                         (test == &header || test->merge == 0);
    const int step = region(f, header.continue_target, {header.label});
    int body = 0;
    std::optional<std::int64_t> trips;
    if (counted) {
      body = region(f, test->successors[0], stops);
      trips = trip_count(f, header, *test, construct);
    } else {
      body = block(header) + kPs30BreakSlots;
      for (std::uint32_t next : header.successors) body += region(f, next, stops);
    }
    // ps_3_0 cannot index registers with a computed index: such a loop is unrolled.
    if (indexes_dynamically(f, construct)) {
      return static_cast<int>(trips.value_or(1)) * body;
    }
    return kPs30LoopSlots + body + step + kPs30EndloopSlots;
  }

  // Trip count of `for (i = a; i <op> b; i += s)` with constant a, b, s, in
  // the unoptimized memory form (i a Function variable); nullopt otherwise.
  std::optional<std::int64_t> trip_count(const SpvFunction& f, const SpvBlock& header,
                                         const SpvBlock& test, const Labels& construct) const {
    const SpvInstruction* cond = m_.def(m_.instructions()[test.end - 1].operand(0));
    if (!cond || !compare(cond->op, 0, 0).has_value()) return std::nullopt;
    const bool counter_left = !m_.int_constant(cond->operand(0));
    const auto bound = m_.int_constant(cond->operand(counter_left ? 1 : 0));
    const std::uint32_t counter = loaded_pointer(cond->operand(counter_left ? 0 : 1));
    if (!bound || counter == 0) return std::nullopt;
    std::optional<std::int64_t> init, step;
    int stores_inside = 0;
    bool before = true;  // the initializing store precedes the header in layout order
    for (const SpvBlock& b : f.blocks) {
      before = before && b.label != header.label;
      const bool inside = construct.contains(b.label);
      for (std::size_t k = b.first; k < b.end && (before || inside); ++k) {
        const SpvInstruction& in = m_.instructions()[k];
        if (in.op != spv::OpStore || in.operand(0) != counter) continue;
        if (before) init = m_.int_constant(in.operand(1));
        if (inside && ++stores_inside == 1) step = increment(counter, in.operand(1));
      }
    }
    if (stores_inside != 1) return std::nullopt;
    if (!init || !step || *step == 0) return std::nullopt;
    std::int64_t trips = 0;
    const auto holds = [&](std::int64_t i) {
      return *(counter_left ? compare(cond->op, i, *bound) : compare(cond->op, *bound, i));
    };
    for (std::int64_t i = *init; holds(i); i += *step) {
      if (++trips > 65536) return std::nullopt;  // not a loop FXC could unroll either
    }
    return trips;
  }

  std::uint32_t loaded_pointer(std::uint32_t id) const {
    const SpvInstruction* def = m_.def(id);
    return def && def->op == spv::OpLoad ? def->operand(0) : 0;
  }

  // s for `counter + s`, `s + counter` or `counter - s` with constant s.
  std::optional<std::int64_t> increment(std::uint32_t counter, std::uint32_t value) const {
    const SpvInstruction* def = m_.def(value);
    if (!def || (def->op != spv::OpIAdd && def->op != spv::OpISub)) return std::nullopt;
    const bool left = loaded_pointer(def->operand(0)) == counter;
    const auto s = m_.int_constant(def->operand(left ? 1 : 0));
    if (!s || (!left && (def->op == spv::OpISub || loaded_pointer(def->operand(1)) != counter))) {
      return std::nullopt;
    }
    return def->op == spv::OpISub ? -*s : *s;
  }

  bool indexes_dynamically(const SpvFunction& f, const Labels& labels) {
    for (const SpvBlock& b : f.blocks) {
      if (!labels.contains(b.label)) continue;
      for (std::size_t k = b.first; k < b.end; ++k) {
        const SpvInstruction& in = m_.instructions()[k];
        if (in.op == spv::OpFunctionCall && indexes_dynamically(in.operand(0))) return true;
        if (in.op != spv::OpAccessChain && in.op != spv::OpInBoundsAccessChain) continue;
        for (std::size_t i = 1; i < in.operand_count(); ++i) {
          if (!m_.is_constant(in.operand(i))) return true;
        }
      }
    }
    return false;
  }

  bool indexes_dynamically(std::uint32_t function_id) {
    if (auto it = function_indexes_.find(function_id); it != function_indexes_.end()) {
      return it->second;
    }
    function_indexes_[function_id] = false;
    const SpvFunction* f = m_.function(function_id);
    Labels all;
    if (f) {
      for (const SpvBlock& b : f->blocks) all.insert(b.label);
    }
    return function_indexes_[function_id] = f && indexes_dynamically(*f, all);
  }

  const SpirvModule& m_;
  std::set<std::uint32_t> fused_;  // multiplies folded into the add that uses them
  std::map<std::uint32_t, int> function_slots_;
  std::map<std::uint32_t, bool> function_indexes_;
};

}  // namespace

int estimate_ps30_slots(const SpirvModule& module) {
  const SpvFunction* entry = module.entry_point();
  return entry ? Estimator(module).function(entry->id) : 0;
}

}  // namespace penumbra
