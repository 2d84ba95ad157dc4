#include "build_runs.hpp"

#include <cstdio>
#include <utility>

namespace penumbra::bench {

BuildCounts parse_summary(const std::string& output) {
  BuildCounts counts;
  counts.up_to_date = output.find(" is up to date\n") != std::string::npos;
  const std::size_t line = output.rfind("built ");
  if (line != std::string::npos) {
    std::sscanf(output.c_str() + line,
                "built %zu variants (%zu shader files, %zu bytecode files, %zu shaders from",
                &counts.variants, &counts.files, &counts.bytecode, &counts.cached);
  }
  return counts;
}

BuildRunner::BuildRunner(std::filesystem::path root, std::filesystem::path penumbra)
    : root_(std::move(root)),
      penumbra_(std::move(penumbra)),
      env_({{"PENUMBRA_HLSL_COMPILER", ""},
            {"XDG_CACHE_HOME", ""},
            {"HOME", (root_ / "home").string()}}) {
  std::filesystem::create_directories(root_ / "home");
}

Result<Measured> BuildRunner::penumbra(std::vector<std::string> args,
                                       const std::string& log) const {
  args.insert(args.begin(), penumbra_.string());
  auto run = run_child(args, env_.get(), root_ / (log + ".log"));
  if (!run) return run.error();
  if (run->exit_code != 0) {
    return make_error(Error::Kind::compile, "penumbra " + args[1],
                      "exited with " + std::to_string(run->exit_code) + ":\n" + run->output);
  }
  return Measured{run->seconds, run->peak_rss_kb, parse_summary(run->output)};
}

Result<Measured> BuildRunner::build(const std::filesystem::path& manifest,
                                    const std::filesystem::path& out, int jobs,
                                    const std::vector<std::string>& extra) const {
  std::vector<std::string> args = {"build", manifest.string(),   "-o", out.string(),
                                   "-j",    std::to_string(jobs)};
  args.insert(args.end(), extra.begin(), extra.end());
  return penumbra(std::move(args), out.filename().string());
}

double mib(long kb) {
  return static_cast<double>(kb) / 1024.0;
}

void print_row(const std::string& what, double seconds, std::size_t shaders, long rss_kb,
               const std::string& note) {
  const std::string rate =
      shaders > 0 ? std::to_string(static_cast<long>(static_cast<double>(shaders) / seconds)) : "-";
  char rss[32] = "-";
  if (rss_kb > 0) std::snprintf(rss, sizeof rss, "%.0f", mib(rss_kb));
  std::printf("| %s | %.3f | %s | %s | %s |\n", what.c_str(), seconds, rate.c_str(), rss,
              note.c_str());
}

}  // namespace penumbra::bench
