#include "build_cold.hpp"

#include <cstdint>
#include <cstdio>

#include "build_runs.hpp"

namespace penumbra::bench {
namespace {

struct ColdRow {
  std::string what;
  Measured measured;
  std::uintmax_t index_bytes = 0;
};

// One cold build into a new folder under the runner's root, measured, its
// index.json's size kept and the folder removed.
Result<ColdRow> cold_build(const BuildRunner& runner, const std::filesystem::path& manifest,
                           const std::string& what, const std::string& folder, int jobs,
                           std::vector<std::string> extra) {
  const std::filesystem::path out = runner.root() / folder;
  extra.insert(extra.begin(), "--no-cache");
  PENUMBRA_TRY_ASSIGN(Measured measured, runner.build(manifest, out, jobs, extra));
  ColdRow row{what, measured, std::filesystem::file_size(out / "index.json")};
  std::filesystem::remove_all(out);
  return row;
}

void print_rows(const std::vector<ColdRow>& rows) {
  std::printf("| build | wall s | shaders/s | peak RSS MiB | index.json bytes |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const ColdRow& row : rows) {
    print_row(row.what, row.measured.seconds, row.measured.counts.files, row.measured.peak_rss_kb,
              std::to_string(row.index_bytes));
  }
  std::printf("\n");
  const ColdRow& first = rows.front();
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::printf("%s / %s: %.2fx the time, %.2fx the index\n", rows[i].what.c_str(),
                first.what.c_str(), rows[i].measured.seconds / first.measured.seconds,
                static_cast<double>(rows[i].index_bytes) / static_cast<double>(first.index_bytes));
  }
}

}  // namespace

Status bench_cold_builds(const ColdOptions& options, const std::filesystem::path& manifest) {
  const ScratchRoot scratch("penumbra-bench-cold");
  const BuildRunner runner(scratch.path() / "this", options.penumbra);
  std::vector<ColdRow> rows;
  PENUMBRA_TRY_ASSIGN(ColdRow all,
                      cold_build(runner, manifest, "every form", "all", options.jobs, {}));
  rows.push_back(std::move(all));
  for (const std::string& form : options.forms) {
    PENUMBRA_TRY_ASSIGN(ColdRow one, cold_build(runner, manifest, "--form " + form, "form-" + form,
                                                options.jobs, {"--form", form}));
    rows.push_back(std::move(one));
  }
  if (!options.baseline.empty()) {
    const BuildRunner baseline(scratch.path() / "baseline", options.baseline);
    PENUMBRA_TRY_ASSIGN(ColdRow base, cold_build(baseline, manifest, "baseline, every form", "all",
                                                 options.jobs, {}));
    rows.push_back(std::move(base));
  }
  std::printf("\n%s: %zu variants, %zu shaders in every form; -j%d, cold, no cache\n\n",
              std::filesystem::relative(manifest).string().c_str(),
              rows.front().measured.counts.variants, rows.front().measured.counts.files,
              options.jobs);
  print_rows(rows);
  return {};
}

}  // namespace penumbra::bench
