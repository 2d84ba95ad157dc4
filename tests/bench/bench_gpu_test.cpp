// penumbra_bench_gpu run as CI runs it (on the default device, lavapipe, at
// 64x48 with two variants): it exits 0 and prints the fetch-only ceiling and
// one complete row per variant, each figure plausible.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct BenchRun {
  int exit_code = -1;
  std::string out;  // stdout and stderr
};

BenchRun run_bench(const std::string& args) {
  BenchRun run;
  const std::string command = std::string(PENUMBRA_BENCH_GPU) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
    run.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

// A table row: technique and the nine figures after the variant's name.
struct Row {
  std::string technique;
  std::vector<double> figures;  // depth, mip, query ms; Mpx/s; reads/px; Gtexel/s; /ceiling; mae
};

std::map<std::string, Row> table_rows(const std::string& out) {
  static const std::regex row(R"(^(\S+) +(\S+)((?: +-?[0-9]+\.[0-9]+){8})$)");
  std::map<std::string, Row> rows;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    Row r{m[2], {}};
    std::istringstream numbers(m[3].str());
    for (double v; numbers >> v;) r.figures.push_back(v);
    rows[m[1]] = r;
  }
  return rows;
}

TEST(BenchGpu, SmallStageTwoVariants) {
  const BenchRun run = run_bench("--size 64x48 --variant pcf_grid_k3 --variant minmax_pcf_k8");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("64x48"), std::string::npos) << run.out;

  std::smatch ceiling;
  ASSERT_TRUE(std::regex_search(
      run.out, ceiling,
      std::regex(
          R"(fetch-only ceiling: 64 comparisons/px with pcf_grid_k3's sampler: ([0-9.]+) ms, ([0-9.]+) reads/px, ([0-9.]+) Gtexel/s)")))
      << run.out;
  EXPECT_GT(std::stod(ceiling[1]), 0.0);
  EXPECT_EQ(std::stod(ceiling[2]), 256.0);  // 4 texels per bilinear comparison
  EXPECT_GT(std::stod(ceiling[3]), 0.0);

  const auto rows = table_rows(run.out);
  ASSERT_EQ(rows.size(), 2u) << run.out;
  for (const char* name : {"pcf_grid_k3", "minmax_pcf_k8"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(rows.count(name)) << run.out;
    const Row& r = rows.at(name);
    ASSERT_EQ(r.figures.size(), 8u);
    EXPECT_GT(r.figures[0], 0.0) << "depth_ms";
    EXPECT_GT(r.figures[2], 0.0) << "query_ms";
    EXPECT_GT(r.figures[3], 0.0) << "Mpx/s";
    EXPECT_GT(r.figures[4], 0.0) << "reads/px";
    EXPECT_GT(r.figures[5], 0.0) << "Gtexel/s";
    EXPECT_GT(r.figures[6], 0.0) << "/ceiling";
    EXPECT_GE(r.figures[7], 0.0) << "exact_mae";
    EXPECT_LT(r.figures[7], 0.5) << "exact_mae";
  }
  EXPECT_EQ(rows.at("pcf_grid_k3").technique, "pcf_grid");
  EXPECT_EQ(rows.at("pcf_grid_k3").figures[1], 0.0) << "pcf_grid builds no mip";
  EXPECT_GT(rows.at("minmax_pcf_k8").figures[1], 0.0) << "minmax_pcf's mip build";
  // pcf_grid_k3: 3x3 bilinear comparisons on every pixel that samples the map.
  EXPECT_LE(rows.at("pcf_grid_k3").figures[4], 36.0);
}

TEST(BenchGpu, UnknownVariantIsBadInput) {
  const BenchRun run = run_bench("--size 64x48 --variant no_such_variant");
  EXPECT_EQ(run.exit_code, 2) << run.out;
  EXPECT_NE(run.out.find("--variant no_such_variant"), std::string::npos) << run.out;
}

}  // namespace
