// The queue that hands the plan's pairs to verify's device threads
// (verify/src/pair_queue.hpp), without a device: each pair once, each
// target's to its own thread in plan order until that thread runs out, from
// any number of threads; each thread's own targets; the pair that reports each map's checks; a
// variant's references shared by its pairs and let go after its last.
#include "pair_queue.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <mutex>
#include <set>
#include <thread>

#include "library_entries.hpp"

namespace penumbra::testing {
namespace {

using ::testing::ElementsAre;

// planned_library() and a variant that prepares nothing: its maps and mip
// are minmax_pcf's.
VerifyPlan plan() {
  Library lib = planned_library();
  lib.variants.push_back(planned_variant("minmax_again", Technique::minmax_pcf, {Target::spirv}));
  auto planned = plan_verify(lib, {});
  EXPECT_TRUE(planned) << (planned ? "" : planned.error().to_string());
  return planned ? *planned : VerifyPlan{};
}

std::string flags(const PairQueue::Claim& c) {
  return std::to_string(c.variant) + "." + std::to_string(c.pair) +
         (c.reports_maps ? " maps" : "") + (c.reports_minmax ? " minmax" : "");
}

TEST(PairQueue, HandsOutEveryPairInPlanOrderWithWhatItReports) {
  const VerifyPlan p = plan();
  PairQueue queue(p, 1);
  std::vector<std::string> claimed;
  while (const auto claim = queue.next(0)) claimed.push_back(flags(*claim));
  // hard draws spirv's and glsl450's linear maps, pcss_perspective spirv's
  // perspective ones; minmax_pcf builds the first mips, minmax_dx9 draws and
  // builds hlsl_dx9's, minmax_again neither.
  EXPECT_THAT(claimed, ElementsAre("0.0 maps", "0.1 maps", "1.0 maps", "2.0 minmax", "2.1 minmax",
                                   "3.0 maps minmax", "4.0"));
  EXPECT_FALSE(queue.next(0));
}

TEST(PairQueue, NamesEachThreadsOwnTargetsInPlanOrder) {
  const VerifyPlan p = plan();
  const PairQueue queue(p, 2);
  // spirv and hlsl_dx9 (targets 0 and 6) are thread 0's, glsl450 thread 1's.
  EXPECT_THAT(queue.own_targets(0), ElementsAre(Target::spirv, Target::hlsl_dx9));
  EXPECT_THAT(queue.own_targets(1), ElementsAre(Target::glsl450));
  const PairQueue one(p, 1);
  EXPECT_THAT(one.own_targets(0), ElementsAre(Target::spirv, Target::glsl450, Target::hlsl_dx9));
}

TEST(PairQueue, GivesEachThreadItsTargetsThenTheRest) {
  const VerifyPlan p = plan();
  PairQueue queue(p, 2);
  // spirv and hlsl_dx9 (targets 0 and 6) are thread 0's, glsl450 thread 1's.
  EXPECT_EQ(flags(*queue.next(1)), "0.1 maps");
  EXPECT_EQ(flags(*queue.next(1)), "2.1 minmax");
  // Thread 1 has none left: it takes thread 0's next, which thread 0 would
  // have taken itself.
  EXPECT_EQ(flags(*queue.next(1)), "0.0 maps");
  EXPECT_EQ(flags(*queue.next(0)), "1.0 maps");
  EXPECT_EQ(flags(*queue.next(0)), "2.0 minmax");
  EXPECT_EQ(flags(*queue.next(1)), "3.0 maps minmax");
  EXPECT_EQ(flags(*queue.next(0)), "4.0");
  EXPECT_FALSE(queue.next(0));
  EXPECT_FALSE(queue.next(1));
}

// A variant's pairs claimed out of plan order, its last first: the earlier
// one still gets the references.
TEST(PairQueue, KeepsAVariantsReferencesUntilEveryPairIsClaimed) {
  const VerifyPlan p = plan();
  PairQueue queue(p, 2);
  const auto last = queue.next(1);  // hard [glsl450]
  ASSERT_TRUE(last && last->references);
  EXPECT_EQ(last->variant, 0u);
  EXPECT_EQ(last->pair, 1u);
  const auto first = queue.next(0);  // hard [spirv]
  ASSERT_TRUE(first && first->references);
  EXPECT_EQ(first->references, last->references);
  EXPECT_EQ(first->references.use_count(), 2);  // the two claims': the queue let go
}

TEST(PairQueue, SharesAVariantsReferencesAndLetsGoAfterItsLastPair) {
  const VerifyPlan p = plan();
  PairQueue queue(p, 1);
  const auto first = queue.next(0);
  ASSERT_TRUE(first && first->references);
  EXPECT_EQ(first->references.use_count(), 2);  // the claim's and the queue's
  const auto second = queue.next(0);            // hard's last pair
  ASSERT_TRUE(second);
  EXPECT_EQ(second->references, first->references);
  EXPECT_EQ(first->references.use_count(), 2);  // the two claims': the queue let go
  const auto third = queue.next(0);
  ASSERT_TRUE(third);
  EXPECT_NE(third->references, first->references);
}

TEST(PairQueue, GivesEachPairOnceToManyThreads) {
  const VerifyPlan p = plan();
  PairQueue queue(p, 4);
  std::mutex mutex;
  std::vector<std::string> claimed;
  std::vector<std::jthread> threads;
  for (std::size_t t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      std::vector<std::string> mine;
      while (const auto claim = queue.next(t)) mine.push_back(flags(*claim));
      const std::lock_guard lock(mutex);
      claimed.insert(claimed.end(), mine.begin(), mine.end());
    });
  }
  threads.clear();
  EXPECT_EQ(claimed.size(), p.pair_count());
  EXPECT_EQ(std::set<std::string>(claimed.begin(), claimed.end()).size(), p.pair_count());
}

}  // namespace
}  // namespace penumbra::testing
