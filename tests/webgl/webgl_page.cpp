#include "webgl_page.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <set>

#include "chromium_page.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPlaceholder = "PENUMBRA_PROGRAMS_JSON";

// The names an engine passes to WebGL for one program, over every variant
// that uses it.
struct Lookup {
  std::set<std::string> blocks, uniforms, samplers, attributes, outputs;
};

void add_names(const PassReflection& pass, Lookup& lookup) {
  for (const StageBindings* stage : {&pass.vert, &pass.frag}) {
    for (const BlockBinding& block : stage->blocks) {
      lookup.blocks.insert(block.name);
      for (const ConstantBinding& member : block.members) lookup.uniforms.insert(member.name);
    }
    for (const ConstantBinding& uniform : stage->uniforms) lookup.uniforms.insert(uniform.name);
    for (const TextureBinding& texture : stage->textures) lookup.samplers.insert(texture.name);
  }
  for (const VertexAttribute& input : pass.vertex_inputs) lookup.attributes.insert(input.name);
  for (const RenderTarget& target : pass.render_targets) lookup.outputs.insert(target.name);
}

// webgl_proof.html's input: every essl300 source once, each program once,
// and every format a pass renders into.
Result<nlohmann::json> page_input(const Library& library) {
  nlohmann::json shaders = nlohmann::json::object();
  std::map<std::string, std::pair<PassFiles, Lookup>> programs;
  std::map<std::string, bool> formats;  // name -> depth attachment
  for (const LibraryVariant& variant : library.variants) {
    for (const auto& [pass, targets] : variant.passes) {
      const auto files = targets.find(Target::essl300);
      if (files == targets.end()) continue;
      for (const std::string* path : {&files->second.vert, &files->second.frag}) {
        if (shaders.contains(*path)) continue;
        PENUMBRA_TRY_ASSIGN(shaders[*path], read_file(library.root / *path));
      }
      auto& program = programs[program_key(files->second)];
      program.first = files->second;
      const auto reflection = variant.reflection.find(pass);
      if (reflection == variant.reflection.end()) continue;
      const auto essl = reflection->second.find(Target::essl300);
      if (essl == reflection->second.end()) continue;  // the check reports it
      add_names(essl->second, program.second);
      for (const RenderTarget& target : essl->second.render_targets) formats[target.format] = false;
      if (!essl->second.depth_target.empty()) formats[essl->second.depth_target] = true;
    }
  }
  nlohmann::json input = {{"shaders", std::move(shaders)},
                          {"formats", nlohmann::json::array()},
                          {"programs", nlohmann::json::array()}};
  for (const auto& [name, depth] : formats) {
    input["formats"].push_back({{"name", name}, {"depth", depth}});
  }
  for (const auto& [key, program] : programs) {
    const Lookup& names = program.second;
    input["programs"].push_back({{"vert", program.first.vert},
                                 {"frag", program.first.frag},
                                 {"lookup",
                                  {{"blocks", names.blocks},
                                   {"uniforms", names.uniforms},
                                   {"samplers", names.samplers},
                                   {"attributes", names.attributes},
                                   {"outputs", names.outputs}}}});
  }
  return input;
}

}  // namespace

std::string program_key(const PassFiles& files) {
  return files.vert + "|" + files.frag;
}

Result<nlohmann::json> run_webgl(const Library& library) {
  const fs::path template_path =
      fs::path(PENUMBRA_SOURCE_DIR) / "tests" / "webgl" / "webgl_proof.html";
  PENUMBRA_TRY_ASSIGN(std::string page, read_file(template_path));
  const auto at = page.find(kPlaceholder);
  if (at == std::string::npos) {
    return make_error(Error::Kind::internal, template_path.string(),
                      "has no " + std::string(kPlaceholder));
  }
  PENUMBRA_TRY_ASSIGN(const nlohmann::json input, page_input(library));
  page.replace(at, kPlaceholder.size(), script_safe(input.dump()));

  const fs::path dir =
      fs::path(::testing::TempDir()) / ("penumbra-webgl-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path page_path = dir / "webgl_proof.html";
  PENUMBRA_TRY(write_file(page_path, page));
  PENUMBRA_TRY_ASSIGN(const std::string text, run_chromium_page(page_path, CHROMIUM_EXECUTABLE));
  nlohmann::json result = nlohmann::json::parse(text, nullptr, false);
  if (result.is_discarded()) {
    return make_error(Error::Kind::internal, page_path.string(), "the result is not JSON: " + text);
  }
  std::error_code ignored;
  fs::remove_all(dir, ignored);  // kept when the run fails, for its page and log
  return result;
}

}  // namespace penumbra::testing
