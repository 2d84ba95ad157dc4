// `penumbra report` runs the Direct3D runtimes as verify does: a library
// with bytecode gets a row per runtime on the report's stage, drawn by that
// runtime (maps included) and equal to the CPU reference on that map.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "cli_harness.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

constexpr const char* kManifest =
    R"({"schema": 1, "targets": ["hlsl_dx9", "hlsl_dx10", "hlsl_dx11"],
        "sets": [{"technique": "hard"}, {"technique": "minmax_pcf", "kernel": 8}]})";

TEST(ReportOnRuntimes, EveryRuntimeHasItsRowsAndMatchesTheReference) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
  ScratchDir dir("d3d-report");
  const auto manifest = dir.write("manifest.json", kManifest);
  const auto lib = dir.path() / "lib";
  const CliRun built = run_penumbra("build '" + manifest.string() + "' -o '" + lib.string() +
                                    "' --hlsl-compiler '" + compiler->string() + "'");
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const CliRun report = run_penumbra("report '" + lib.string() + "' --no-gl");
  ASSERT_EQ(report.exit_code, 0) << report.out << report.err;
  auto text = read_file(lib / "report" / "report.json");
  ASSERT_TRUE(text.ok()) << text.error().to_string();
  const nlohmann::json rows = nlohmann::json::parse(*text).at("rows");
  std::set<std::string> runtimes;
  for (const auto& row : rows) {
    const std::string path = row.at("path");
    if (!path.starts_with("d3d")) continue;
    runtimes.insert(path);
    const std::string label = row.at("variant").get<std::string>() + " on " + path;
    EXPECT_EQ(row.at("status"), "ok") << label;
    EXPECT_NE(row.at("device").get<std::string>().find("Wine's Direct3D"), std::string::npos)
        << label;
    EXPECT_LT(row.at("figures").at("reference_max").get<double>(), 1e-5) << label;
  }
  EXPECT_EQ(runtimes, (std::set<std::string>{"d3d9", "d3d10", "d3d11"}));
}

}  // namespace
}  // namespace penumbra::testing
