// A library built in the function form alone (`penumbra build --form
// function`): verify checks the function forms it has, says of every scene
// run that the query form was not built, and passes; the report draws what it
// can and says the same.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_harness.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

constexpr const char* kManifest = R"({"schema": 1, "targets": ["spirv", "glsl450"],
  "sets": [{"technique": "hard"},
           {"technique": "pcss", "blocker_samples": 16, "pcf_samples": 16,
            "disk": "whitepaper16"}]})";

constexpr const char* kLacking = "built without the query form (its forms: function)";

class FormsCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new ScratchDir("forms");
    const auto manifest = dir_->write("manifest.json", kManifest);
    const CliRun built = run_penumbra("build '" + manifest.string() + "' -q --form function -o '" +
                                      lib().string() + "'");
    ASSERT_EQ(built.exit_code, 0) << built.err;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::filesystem::path lib() { return dir_->path() / "lib"; }
  static inline ScratchDir* dir_ = nullptr;
};

TEST_F(FormsCommand, VerifyChecksTheFunctionFormsAndSaysTheQueryFormWasNotBuilt) {
  const CliRun run = run_penumbra("verify '" + lib().string() + "' --no-wine");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr(kLacking));
  const auto text = read_file(lib() / "verify.json");
  ASSERT_TRUE(text.ok()) << text.error().to_string();
  const nlohmann::json report = nlohmann::json::parse(*text);
  EXPECT_TRUE(report.at("pass").get<bool>());
  EXPECT_EQ(report.at("runs").get<int>(), 0);
  EXPECT_TRUE(report.at("deferred_mask").empty());
  // glsl450's function form for each variant, drawn on the Vulkan and GL paths.
  ASSERT_GE(report.at("function_form").size(), 2u);
  for (const auto& check : report.at("function_form")) {
    EXPECT_TRUE(check.at("pass").get<bool>()) << check.dump();
  }
  ASSERT_EQ(report.at("variants").size(), 2u);
  for (const auto& variant : report.at("variants")) {
    ASSERT_FALSE(variant.at("runs").empty());
    for (const auto& run_json : variant.at("runs")) {
      EXPECT_EQ(run_json.at("not_executed").get<std::string>(), kLacking) << run_json.dump();
    }
  }
}

TEST_F(FormsCommand, ReportSaysWhatTheLibraryLacks) {
  const CliRun run = run_penumbra("report '" + lib().string() + "' -q --no-wine -o '" +
                                  (dir_->path() / "report").string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  bool said = false;
  for (const auto& [name, bytes] : read_tree(dir_->path() / "report")) {
    said = said || bytes.find(kLacking) != std::string::npos;
  }
  EXPECT_TRUE(said) << "no file of the report says the query form was not built";
}

}  // namespace
}  // namespace penumbra::testing
