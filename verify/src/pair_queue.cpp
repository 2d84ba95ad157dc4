#include "pair_queue.hpp"

#include <algorithm>
#include <set>

namespace penumbra {

PairQueue::PairQueue(const VerifyPlan& plan, std::size_t threads)
    : own_(std::max<std::size_t>(threads, 1)), own_targets_(own_.size()) {
  std::set<MapKey> read, built;
  for (std::size_t v = 0; v < plan.variants.size(); ++v) {
    const std::vector<PlannedPair>& pairs = plan.variants[v].pairs;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const bool minmax = pairs[p].minmax_preparer.has_value();
      claims_.push_back({.variant = v,
                         .pair = p,
                         .reports_maps = read.insert(pairs[p].maps).second,
                         .reports_minmax = minmax && built.insert(pairs[p].maps).second});
      const std::size_t owner = static_cast<std::size_t>(pairs[p].target) % own_.size();
      own_[owner].push_back(claims_.size() - 1);
      if (std::ranges::find(own_targets_[owner], pairs[p].target) == own_targets_[owner].end()) {
        own_targets_[owner].push_back(pairs[p].target);
      }
    }
    // Made before any check can ask for them; empty until one does.
    references_.push_back(variant_references());
    unclaimed_.push_back(pairs.size());
  }
}

std::optional<PairQueue::Claim> PairQueue::next(std::size_t thread) {
  const std::lock_guard lock(mutex_);
  // From the front of a queue: whoever takes a map's first pair takes the
  // plan's first, before any other of that map.
  std::deque<std::size_t>* from = &own_[thread % own_.size()];
  if (from->empty()) {
    from = &*std::ranges::max_element(
        own_, [](const auto& a, const auto& b) { return a.size() < b.size(); });
  }
  if (from->empty()) return std::nullopt;
  Claim claim = claims_[from->front()];
  from->pop_front();
  std::shared_ptr<VariantReferences>& references = references_[claim.variant];
  // The last of its pairs to be claimed, whichever it is, takes the queue's
  // share: its checks free them when done, as every other pair's have.
  claim.references = --unclaimed_[claim.variant] == 0 ? std::move(references) : references;
  return claim;
}

}  // namespace penumbra
