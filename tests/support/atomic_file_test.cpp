#include "penumbra/support/atomic_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/support/file.hpp"
#include "temp_dir.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// The names in `dir`, so a test can see that nothing else was left behind.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(WriteFileAtomic, ReplacesTheFileAndLeavesNoTemporary) {
  testing::TempDir dir;
  write_text(dir.path() / "f.txt", "old");
  ASSERT_TRUE(write_file_atomic(dir.path() / "f.txt", "new contents"));
  EXPECT_EQ(read_text(dir.path() / "f.txt"), "new contents");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"f.txt"});
}

TEST(WriteFileAtomic, MissingDirectoryIsAnIoError) {
  testing::TempDir dir;
  const auto status = write_file_atomic(dir.path() / "no" / "f.txt", "x");
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().kind, Error::Kind::io);
  EXPECT_NE(status.error().where.find("f.txt"), std::string::npos);
}

// The user learns why: the temporary's name and the system's reason.
TEST(WriteFileAtomic, AnUncreatableTemporaryNamesItAndTheSystemsReason) {
  testing::TempDir dir;
  write_text(dir.path() / "plain", "a file, not a folder");
  const auto status = write_file_atomic(dir.path() / "plain" / "v.pfm", "x");
  ASSERT_FALSE(status.ok());
  const std::string message = status.error().message;
  EXPECT_EQ(
      message.rfind(
          "cannot create temporary file " + (dir.path() / "plain").string() + "/.v.pfm.tmp-", 0),
      0u)
      << message;
  EXPECT_NE(message.find(": Not a directory"), std::string::npos) << message;
}

TEST(WriteFile, AFailureNamesWhatFailedAndTheSystemsReason) {
  testing::TempDir dir;
  const auto status = write_file(dir.path() / "missing" / "f.bin", "x");
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().kind, Error::Kind::io);
  EXPECT_EQ(status.error().message, "cannot create the file: No such file or directory");
  ASSERT_TRUE(write_file(dir.path() / "f.bin", std::string(3, '\0')));
  EXPECT_EQ(read_text(dir.path() / "f.bin"), std::string(3, '\0'));
}

TEST(StagedDirectory, StagingIsAHiddenSibling) {
  testing::TempDir dir;
  auto staged = StagedDirectory::create(dir.path() / "out");
  ASSERT_TRUE(staged.ok()) << staged.error().to_string();
  EXPECT_EQ(staged->staging().parent_path(), dir.path());
  EXPECT_EQ(staged->staging().filename().string().rfind(".out.staging-", 0), 0u);
  EXPECT_TRUE(fs::is_directory(staged->staging()));
}

TEST(StagedDirectory, WithoutCommitLeavesNothing) {
  testing::TempDir dir;
  fs::create_directory(dir.path() / "out");
  write_text(dir.path() / "out" / "keep.txt", "previous");
  {
    auto staged = StagedDirectory::create(dir.path() / "out");
    ASSERT_TRUE(staged.ok()) << staged.error().to_string();
    write_text(staged->staging() / "partial.txt", "half");
  }
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out"});
  EXPECT_EQ(entries(dir.path() / "out"), std::vector<std::string>{"keep.txt"});
  EXPECT_EQ(read_text(dir.path() / "out" / "keep.txt"), "previous");
}

TEST(StagedDirectory, CommitReplacesTheFinalDirectory) {
  testing::TempDir dir;
  fs::create_directory(dir.path() / "out");
  write_text(dir.path() / "out" / "stale.txt", "old");
  {
    auto staged = StagedDirectory::create(dir.path() / "out");
    ASSERT_TRUE(staged.ok()) << staged.error().to_string();
    write_text(staged->staging() / "index.json", "{}");
    ASSERT_TRUE(staged->commit());
  }
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out"});
  EXPECT_EQ(entries(dir.path() / "out"), std::vector<std::string>{"index.json"});
}

TEST(StagedDirectory, CommitCreatesAMissingFinalDirectory) {
  testing::TempDir dir;
  auto staged = StagedDirectory::create(dir.path() / "a" / "b" / "out/");
  ASSERT_TRUE(staged.ok()) << staged.error().to_string();
  write_text(staged->staging() / "x.txt", "x");
  ASSERT_TRUE(staged->commit());
  EXPECT_EQ(read_text(dir.path() / "a" / "b" / "out" / "x.txt"), "x");
  EXPECT_EQ(entries(dir.path() / "a" / "b"), std::vector<std::string>{"out"});
}

TEST(StagedDirectory, MoveTransfersTheStaging) {
  testing::TempDir dir;
  std::optional<Result<StagedDirectory>> staged(StagedDirectory::create(dir.path() / "out"));
  ASSERT_TRUE(staged->ok());
  const fs::path staging = (*staged)->staging();
  StagedDirectory owner(std::move(**staged));
  staged.reset();  // the moved-from object must not remove what it gave away
  EXPECT_TRUE(fs::is_directory(staging));
  ASSERT_TRUE(owner.commit());
  EXPECT_TRUE(fs::is_directory(dir.path() / "out"));
}

// One writer at a time: a second create() for the same directory, even in
// this process, is refused until the first is gone.
TEST(StagedDirectory, ASecondWriterIsRefusedWhileTheFirstStages) {
  testing::TempDir dir;
  {
    auto first = StagedDirectory::create(dir.path() / "out");
    ASSERT_TRUE(first.ok()) << first.error().to_string();
    const auto second = StagedDirectory::create(dir.path() / "out");
    ASSERT_FALSE(second.ok());
    EXPECT_NE(second.error().message.find("another penumbra process is writing"), std::string::npos)
        << second.error().to_string();
    EXPECT_EQ(second.error().where, (dir.path() / "out").string());
    // A different output directory beside it has its own lock.
    EXPECT_TRUE(StagedDirectory::create(dir.path() / "other").ok());
  }
  EXPECT_TRUE(StagedDirectory::create(dir.path() / "out").ok());
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{});
}

// What a killed writer leaves: a staging tree, and an old tree beside an
// output that still exists. Both go; other names are kept.
TEST(StagedDirectory, CreateRemovesWhatDeadWritersLeft) {
  testing::TempDir dir;
  fs::create_directories(dir.path() / "out");
  write_text(dir.path() / "out" / "index.json", "current");
  for (const char* name : {".out.staging-0123456789abcdef", ".out.old-fedcba9876543210"}) {
    fs::create_directories(dir.path() / name / "sub");
    write_text(dir.path() / name / "sub" / "f.txt", "stale");
  }
  // Not this output's: another output named "out.staging-x", and a user's file.
  fs::create_directories(dir.path() / ".out.staging-x.staging-0123456789abcdef");
  write_text(dir.path() / ".out.notes", "mine");
  {
    auto staged = StagedDirectory::create(dir.path() / "out");
    ASSERT_TRUE(staged.ok()) << staged.error().to_string();
  }
  EXPECT_EQ(
      entries(dir.path()),
      (std::vector<std::string>{".out.notes", ".out.staging-x.staging-0123456789abcdef", "out"}));
  EXPECT_EQ(read_text(dir.path() / "out" / "index.json"), "current");
}

// A commit by two renames that died between them leaves no output and the
// previous tree aside: create() puts it back.
TEST(StagedDirectory, CreatePutsBackAnOutputLeftAside) {
  testing::TempDir dir;
  fs::create_directories(dir.path() / ".out.old-0123456789abcdef");
  write_text(dir.path() / ".out.old-0123456789abcdef" / "index.json", "previous");
  fs::create_directories(dir.path() / ".out.staging-fedcba9876543210");
  write_text(dir.path() / ".out.staging-fedcba9876543210" / "index.json", "unfinished");
  {
    auto staged = StagedDirectory::create(dir.path() / "out");
    ASSERT_TRUE(staged.ok()) << staged.error().to_string();
  }
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out"});
  EXPECT_EQ(read_text(dir.path() / "out" / "index.json"), "previous");
}

TEST(StagedDirectory, CommitLeavesNoSiblingBehind) {
  testing::TempDir dir;
  for (const char* text : {"first", "second"}) {
    auto staged = StagedDirectory::create(dir.path() / "out");
    ASSERT_TRUE(staged.ok()) << staged.error().to_string();
    write_text(staged->staging() / "index.json", text);
    ASSERT_TRUE(staged->commit());
    EXPECT_TRUE(staged->leftover().empty());
  }
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out"});
  EXPECT_EQ(read_text(dir.path() / "out" / "index.json"), "second");
}

}  // namespace
}  // namespace penumbra
