// The plan's (variant, target) pairs handed out to verify's device threads
// one at a time, from any thread. Each target belongs to one thread, which
// takes its pairs in plan order, so that each target's maps, pipelines and
// Wine runtime are made on one thread's devices only; a thread with none
// of its own left takes the next pair of the thread with the most left.
// Each thread prepares a target's maps (and min-max mip) on the first pair
// it runs that reads them; the checks of that preparation are reported by
// whichever holds the plan's first such pair, which prepares them there as
// one thread alone would, so that the report is the same whatever the
// thread count.
#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "scene_checks.hpp"
#include "verify_plan.hpp"

namespace penumbra {

class PairQueue {
 public:
  struct Claim {
    std::size_t variant = 0;  // in VerifyPlan::variants
    std::size_t pair = 0;     // in that variant's pairs
    // Its variant's, shared by the variant's pairs; the queue lets go of
    // them once every pair of the variant is claimed.
    std::shared_ptr<VariantReferences> references = {};
    bool reports_maps = false;    // the plan's first pair that reads its maps
    bool reports_minmax = false;  // the plan's first pair that builds their min-max mip
  };

  // For `threads` device threads (at least 1).
  PairQueue(const VerifyPlan& plan, std::size_t threads);

  // Device thread `thread`'s next pair; none once every pair is claimed.
  std::optional<Claim> next(std::size_t thread);
  // The targets whose pairs belong to device thread `thread`, in plan order.
  const std::vector<Target>& own_targets(std::size_t thread) const {
    return own_targets_[thread % own_targets_.size()];
  }

 private:
  std::mutex mutex_;
  std::vector<Claim> claims_;                     // in plan order, without their references
  std::vector<std::deque<std::size_t>> own_;      // per thread: its pairs left, in plan order
  std::vector<std::vector<Target>> own_targets_;  // per thread: the targets of its pairs
  std::vector<std::shared_ptr<VariantReferences>> references_;  // per planned variant
  std::vector<std::size_t> unclaimed_;  // per planned variant: its pairs left
};

}  // namespace penumbra
