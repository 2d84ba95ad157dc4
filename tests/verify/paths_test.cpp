// The table of execution paths (verify/src/paths.cpp): the names verify.json
// and --path use, in report order, and what each skip flag skips.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "penumbra/verify/paths.hpp"

namespace penumbra::testing {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

TEST(ExecutionPaths, AreListedInReportOrder) {
  EXPECT_EQ(path_names(), "vulkan, bytecode, gl, d3d9, d3d10, d3d11");
  std::vector<std::string_view> names;
  for (const ExecutionPath& path : execution_paths()) {
    names.push_back(path.name);
    EXPECT_FALSE(path.needs.empty()) << path.name;
    EXPECT_TRUE(is_path_name(path.name));
  }
  EXPECT_THAT(names, ElementsAre("vulkan", "bytecode", "gl", "d3d9", "d3d10", "d3d11"));
  EXPECT_FALSE(is_path_name("d3d12"));
  EXPECT_FALSE(is_path_name(""));
}

TEST(ExecutionPaths, EachSkipFlagSkipsItsRows) {
  EXPECT_THAT(paths_skipped_by("--no-gl"), ElementsAre("gl"));
  EXPECT_THAT(paths_skipped_by("--no-wine"), ElementsAre("d3d9", "d3d10", "d3d11"));
  EXPECT_THAT(paths_skipped_by("--no-such-flag"), IsEmpty());
  EXPECT_THAT(paths_skipped_by(""), IsEmpty());  // the paths without a flag
}

}  // namespace
}  // namespace penumbra::testing
