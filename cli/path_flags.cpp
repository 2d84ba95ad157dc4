#include "path_flags.hpp"

#include <algorithm>

#include "penumbra/support/text.hpp"
#include "penumbra/verify/paths.hpp"

namespace penumbra::cli {

void add_skip_flags(CLI::App* cmd, std::vector<std::string>& skipped) {
  std::vector<std::string_view> added;
  for (const ExecutionPath& path : execution_paths()) {
    if (path.skip_flag.empty() || std::ranges::find(added, path.skip_flag) != added.end()) {
      continue;
    }
    added.push_back(path.skip_flag);
    const std::vector<std::string> paths = paths_skipped_by(path.skip_flag);
    const std::string names = join(std::vector<std::string_view>(paths.begin(), paths.end()), ", ");
    cmd->add_flag_callback(
        std::string(path.skip_flag),
        [&skipped, paths] { skipped.insert(skipped.end(), paths.begin(), paths.end()); },
        "Skip the " + names +
            (paths.size() > 1 ? " paths, reporting their" : " path, reporting its") +
            " runs not executed (needs " + std::string(path.needs) + ")");
  }
}

Status check_path_names(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    if (!is_path_name(path)) {
      return make_error(Error::Kind::bad_input, "--path " + path,
                        "unknown execution path; allowed: " + path_names());
    }
  }
  return {};
}

}  // namespace penumbra::cli
