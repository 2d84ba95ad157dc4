// The table of execution paths: each row names a path and makes its
// backend, so that verify, the report and the CLI read one list.
#include "penumbra/verify/paths.hpp"

#include <algorithm>

#include "backend.hpp"
#include "penumbra/d3d/engine.hpp"
#include "penumbra/support/text.hpp"

namespace penumbra {
namespace {

// What a row's backend is made from: `not_requested` is the reason its runs
// are reported not executed when the caller skipped the path, else empty.
struct PathContext {
  Engine& engine;
  const BytecodeTranslator& bytecode;
  std::string not_requested;
};

struct PathRow {
  ExecutionPath path;
  std::unique_ptr<Backend> (*make)(const PathContext&);
};

// On lavapipe, GL runs on llvmpipe too, so both paths use one rasterizer.
std::string gl_device_for(const Engine& engine) {
  return engine.device_info().name.find("llvmpipe") != std::string::npos ? "llvmpipe" : "";
}

constexpr std::string_view kWineNeeds =
    "wine, Xvfb and penumbra_d3d_host.exe, built with mingw-w64";

constexpr PathRow kPaths[] = {
    {{"vulkan", "nothing", ""}, [](const PathContext& c) { return vulkan_backend(c.engine); }},
    {{"bytecode", "vkd3d-compiler (--hlsl-compiler), and a library built with it", ""},
     [](const PathContext& c) { return bytecode_backend(c.engine, c.bytecode); }},
    {{"gl", "EGL and an OpenGL 3.3 driver", "--no-gl"},
     [](const PathContext& c) { return gl_backend(c.not_requested, gl_device_for(c.engine)); }},
    {{"d3d9", kWineNeeds, "--no-wine"},
     [](const PathContext& c) {
       return wine_backend(D3dRuntime::d3d9, c.not_requested, c.bytecode);
     }},
    {{"d3d10", kWineNeeds, "--no-wine"},
     [](const PathContext& c) {
       return wine_backend(D3dRuntime::d3d10, c.not_requested, c.bytecode);
     }},
    {{"d3d11", kWineNeeds, "--no-wine"},
     [](const PathContext& c) {
       return wine_backend(D3dRuntime::d3d11, c.not_requested, c.bytecode);
     }},
};

}  // namespace

std::vector<ExecutionPath> execution_paths() {
  std::vector<ExecutionPath> paths;
  for (const PathRow& row : kPaths) paths.push_back(row.path);
  return paths;
}

std::string path_names() {
  std::vector<std::string_view> names;
  for (const PathRow& row : kPaths) names.push_back(row.path.name);
  return join(names, ", ");
}

bool is_path_name(std::string_view name) {
  return std::ranges::any_of(kPaths, [&](const PathRow& row) { return row.path.name == name; });
}

std::vector<std::string> paths_skipped_by(std::string_view flag) {
  std::vector<std::string> paths;
  for (const PathRow& row : kPaths) {
    if (!flag.empty() && row.path.skip_flag == flag) paths.emplace_back(row.path.name);
  }
  return paths;
}

BytecodeTranslator shared_runs(BytecodeTranslator translator) {
  if (!translator.memo) translator.memo = std::make_shared<Vkd3dMemo>();
  return translator;
}

std::vector<std::unique_ptr<Backend>> all_backends(Engine& engine,
                                                   const BytecodeTranslator& bytecode,
                                                   const std::vector<std::string>& skipped) {
  std::vector<std::unique_ptr<Backend>> backends;
  for (const PathRow& row : kPaths) {
    const bool skip = std::ranges::find(skipped, row.path.name) != skipped.end();
    const std::string flag =
        row.path.skip_flag.empty() ? "" : " (" + std::string(row.path.skip_flag) + ")";
    backends.push_back(row.make({engine, bytecode, skip ? "not requested" + flag : ""}));
  }
  return backends;
}

}  // namespace penumbra
