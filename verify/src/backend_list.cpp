#include "backend.hpp"

namespace penumbra {

bool is_path_name(std::string_view name) {
  for (std::string_view names = kPathNames; !names.empty();) {
    const std::size_t comma = names.find(", ");
    if (names.substr(0, comma) == name) return true;
    names = comma == std::string_view::npos ? std::string_view() : names.substr(comma + 2);
  }
  return false;
}

std::vector<std::unique_ptr<Backend>> all_backends(Engine& engine, BytecodeTranslator bytecode,
                                                   bool gl, bool wine) {
  std::vector<std::unique_ptr<Backend>> backends;
  backends.push_back(vulkan_backend(engine));
  backends.push_back(bytecode_backend(engine, bytecode));
  // On lavapipe, GL runs on llvmpipe too, so both paths use one rasterizer.
  const bool lavapipe = engine.device_info().name.find("llvmpipe") != std::string::npos;
  backends.push_back(gl_backend(gl, lavapipe ? "llvmpipe" : ""));
  for (auto& backend : wine_backends(wine, bytecode)) backends.push_back(std::move(backend));
  return backends;
}

}  // namespace penumbra
