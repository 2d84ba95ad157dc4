#include "penumbra/support/device_selector.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace penumbra {
namespace {

const std::vector<std::string> kNames = {"NVIDIA GeForce", "llvmpipe (LLVM 15)", "AMD 0"};

TEST(DeviceSelectorTest, DigitsAreAnIndexInRange) {
  EXPECT_EQ(match_selector(kNames, "1"), 1u);
  EXPECT_EQ(match_selector(kNames, "01"), 1u);
  EXPECT_EQ(match_selector(kNames, "3"), std::nullopt);
  EXPECT_EQ(match_selector(kNames, "99999999999999999999"), std::nullopt);
}

TEST(DeviceSelectorTest, AnythingElseIsTheFirstNameContainingItIgnoringCase) {
  EXPECT_EQ(match_selector(kNames, "LLVMpipe"), 1u);
  EXPECT_EQ(match_selector(kNames, "e"), 0u);
  EXPECT_EQ(match_selector(kNames, "no-such-gpu"), std::nullopt);
  EXPECT_EQ(match_selector({}, "llvmpipe"), std::nullopt);
}

TEST(DeviceSelectorTest, ListsEveryChoiceAsIndexAndName) {
  EXPECT_EQ(list_choices(kNames), "0: NVIDIA GeForce, 1: llvmpipe (LLVM 15), 2: AMD 0");
  EXPECT_EQ(list_choices({}), "");
}

}  // namespace
}  // namespace penumbra
