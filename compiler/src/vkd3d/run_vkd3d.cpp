#include "vkd3d/run_vkd3d.hpp"

namespace penumbra {

Result<ProcessRun> run_vkd3d(const std::filesystem::path& compiler,
                             std::vector<std::string> arguments,
                             std::chrono::milliseconds timeout) {
  arguments.insert(arguments.begin(), compiler.string());
  auto run = run_process(arguments, timeout);
  if (!run) {
    return make_error(Error::Kind::io, compiler.string(),
                      "cannot run the HLSL compiler (--hlsl-compiler): " + run.error().message);
  }
  return run;
}

}  // namespace penumbra
