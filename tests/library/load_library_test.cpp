// index.json read back by penumbra::library alone: this executable links no
// shader compiler (tests/library/CMakeLists.txt), as an engine that only
// reads a library and draws must not.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "penumbra/library/library.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra {
namespace {

using ::testing::HasSubstr;

// One of the index.json fuzzer's seeds (tests/fuzz/index/).
std::string seed(const char* name) {
  auto text =
      read_file(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "tests" / "fuzz" / "index" / name);
  EXPECT_TRUE(text.ok()) << name;
  return text.ok() ? *text : std::string();
}

TEST(LoadLibrary, ReadsEachVariantsFilesAndReflectionWithoutACompiler) {
  const auto library = parse_library(seed("hard.json"), "lib");
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  const LibraryVariant* hard = library->find("hard");
  ASSERT_NE(hard, nullptr);
  EXPECT_EQ(hard->variant.technique, Technique::hard);
  ASSERT_TRUE(hard->passes.contains(PassKind::query));
  ASSERT_TRUE(hard->reflection.contains(PassKind::query));
  for (const auto& [target, files] : hard->passes.at(PassKind::query)) {
    EXPECT_FALSE(files.frag.empty()) << to_string(target);
    EXPECT_TRUE(hard->reflection.at(PassKind::query).contains(target)) << to_string(target);
  }
}

// index.json's "forms": what was built; a library written before forms on
// demand has every form its technique has.
TEST(LoadLibrary, FormsAreWhatWasBuilt) {
  const std::string hard = seed("hard.json");
  const auto old = parse_library(hard, "lib");
  ASSERT_TRUE(old.ok()) << old.error().to_string();
  EXPECT_EQ(old->find("hard")->variant.forms,
            (std::vector<Form>{Form::query, Form::deferred, Form::function}));

  const std::string targets = R"("targets":["spirv","hlsl_dx9"])";
  ASSERT_NE(hard.find(targets), std::string::npos);
  const auto with_forms = [&](const std::string& forms) {
    std::string text = hard;
    text.replace(text.find(targets), targets.size(), targets + R"(,"forms":)" + forms);
    return parse_library(text, "lib");
  };
  const auto built = with_forms(R"(["function","query"])");
  ASSERT_TRUE(built.ok()) << built.error().to_string();
  EXPECT_EQ(built->find("hard")->variant.forms, (std::vector<Form>{Form::query, Form::function}));

  const auto unknown = with_forms(R"(["query","shadow"])");
  ASSERT_FALSE(unknown.ok());
  EXPECT_THAT(unknown.error().to_string(),
              HasSubstr("/variants/0/forms/1: unknown form 'shadow' for technique hard; allowed: "
                        "query, deferred, function"));
  const auto not_array = with_forms(R"("query")");
  ASSERT_FALSE(not_array.ok());
  EXPECT_THAT(not_array.error().to_string(), HasSubstr("/variants/0/forms"));
}

// Numbers that do not fit their field are errors, not undefined behaviour
// (the index.json fuzzer's finds: an instruction count of 2e115, a schema of
// 1e300, a blur weight of 1e39, a block size of 3e117).
TEST(LoadLibrary, NumbersThatDoNotFitTheirFieldAreErrors) {
  const auto huge = parse_library(seed("huge_integer.json"), "lib");
  ASSERT_FALSE(huge.ok());
  EXPECT_THAT(huge.error().to_string(), HasSubstr("is not a number that fits its field"));
  const std::string hard = seed("hard.json");
  std::string schema = hard;
  schema.replace(schema.find("\"schema\": 4"), 11, "\"schema\": 1e300");
  const auto bad_schema = parse_library(schema, "lib");
  ASSERT_FALSE(bad_schema.ok());
  EXPECT_THAT(bad_schema.error().to_string(), HasSubstr("/schema"));
  const auto block_size = parse_library(seed("huge_reflection_size.json"), "lib");
  ASSERT_FALSE(block_size.ok());
  EXPECT_THAT(block_size.error().to_string(), HasSubstr("/reflections/0"));
  EXPECT_THAT(block_size.error().to_string(), HasSubstr("3e+117 is not a number that fits"));
  // A reflection's integers take no negative, boolean or 33-bit values either.
  const std::string size = "\"size\":96";
  for (const char* number : {"-1", "true", "4294967296", "96.5"}) {
    std::string record = hard;
    record.replace(record.find(size), size.size(), std::string("\"size\":") + number);
    const auto bad = parse_library(record, "lib");
    ASSERT_FALSE(bad.ok()) << number;
    EXPECT_THAT(bad.error().to_string(), HasSubstr("/reflections/0")) << number;
  }
}

}  // namespace
}  // namespace penumbra
