#include "penumbra/support/shard.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace penumbra {
namespace {

using ::testing::HasSubstr;

TEST(Shard, ParsesIOfN) {
  auto shard = parse_shard("3/4", "--shard");
  ASSERT_TRUE(shard.ok());
  EXPECT_EQ(*shard, (Shard{3, 4}));
  EXPECT_EQ(to_string(*shard), "3/4");
  EXPECT_EQ(*parse_shard("1/1", "--shard"), Shard{});
}

TEST(Shard, RejectsAnythingElseNamingTheArgument) {
  for (const char* text : {"", "3", "3/", "/4", "0/4", "1/0", "01/4", "-1/4", "1 /4", "1/4x", "a/b",
                           "1/99999999999"}) {
    auto shard = parse_shard(text, "--shard");
    ASSERT_FALSE(shard.ok()) << text;
    EXPECT_EQ(shard.error().where, std::string("--shard ") + text);
    EXPECT_THAT(shard.error().message, HasSubstr("1 <= I <= N"));
  }
  auto over = parse_shard("3/2", "--shard");
  ASSERT_FALSE(over.ok());
  EXPECT_EQ(over.error().to_string(), "--shard 3/2: I must be in 1..N (1..2)");
}

}  // namespace
}  // namespace penumbra
