#include "penumbra/support/file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>

#include "temp_dir.hpp"

namespace penumbra {
namespace {

using ::testing::HasSubstr;

// Errors keep the system's reason, as strerror words it.
TEST(ReadFile, ErrorsSayWhy) {
  testing::TempDir dir;
  const Result<std::string> missing = read_file(dir.path() / "absent");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().kind, Error::Kind::io);
  EXPECT_EQ(missing.error().where, (dir.path() / "absent").string());
  EXPECT_THAT(missing.error().message, HasSubstr(std::strerror(ENOENT)));

  const Result<std::string> folder = read_file(dir.path());
  ASSERT_FALSE(folder);
  EXPECT_THAT(folder.error().message, HasSubstr(std::strerror(EISDIR)));

  const Result<std::string> unnamed = read_file("");
  ASSERT_FALSE(unnamed);
  EXPECT_THAT(unnamed.error().message, HasSubstr("empty name"));
}

}  // namespace
}  // namespace penumbra
