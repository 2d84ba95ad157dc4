// verify's Memo: one value per distinct key, made once however many
// threads ask for it at the same time, and SceneTruths, which keeps a
// scene's ray cast for every map of it.
#include "memo.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "penumbra/reference/scene.hpp"
#include "scene_truths.hpp"

namespace penumbra {
namespace {

TEST(Memo, MakesEachKeysValueOnceAndKeepsItsAddress) {
  Memo<std::string, int> memo;
  int made = 0;
  const int& a = memo.get("a", [&] { return ++made; });
  const int& b = memo.get("b", [&] { return ++made; });
  EXPECT_EQ(a, 1);
  EXPECT_EQ(b, 2);
  EXPECT_EQ(&memo.get("a", [&] { return ++made; }), &a);
  EXPECT_EQ(made, 2);
}

TEST(Memo, ThreadsAskingForOneKeyAtOnceShareOneMake) {
  Memo<int, std::vector<int>> memo;
  std::atomic<int> made{0};
  std::atomic<int> ready{0};
  constexpr int kThreads = 8;
  std::vector<const std::vector<int>*> seen(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      ++ready;
      while (ready < kThreads) std::this_thread::yield();
      seen[t] = &memo.get(t % 2, [&] {
        ++made;
        // Long enough that the other threads ask while it is being made.
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        return std::vector<int>(1000, t % 2);
      });
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(made, 2);
  for (int t = 0; t < kThreads; ++t) {
    EXPECT_EQ(seen[t], seen[t % 2]) << "thread " << t;
    EXPECT_EQ(seen[t]->front(), t % 2);
  }
}

TEST(SceneTruths, OneRayCastPerSceneAndSizeTheSameAsCastingIt) {
  SceneTruths truths;
  const reference::Scene scene = reference::builtin_scenes().front();
  const auto truth = truths.depth(scene, 64, 48);
  EXPECT_EQ(truths.depth(scene, 64, 48), truth);
  EXPECT_NE(truths.depth(scene, 64, 64), truth);
  reference::Scene moved = scene;
  moved.plane_z0 += 1.0;
  EXPECT_NE(truths.depth(moved, 64, 48), truth);
  const DepthTruth cast = depth_truth(scene, 64, 48);
  EXPECT_EQ(truth->surface.data, cast.surface.data);
  EXPECT_EQ(truth->clear, cast.clear);
}

}  // namespace
}  // namespace penumbra
