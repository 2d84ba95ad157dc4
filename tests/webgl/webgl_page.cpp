#include "webgl_page.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPlaceholder = "PENUMBRA_PROGRAMS_JSON";

// Headless WebGL 2 as root on a machine with no GPU: ANGLE on SwiftShader
// (Chromium refuses it unless told it is meant), no sandbox (root), and
// nothing that reaches the network.
constexpr const char* kFlags =
    " --headless --no-sandbox --disable-gpu-sandbox --use-gl=angle --use-angle=swiftshader"
    " --enable-unsafe-swiftshader --ignore-gpu-blocklist --disable-background-networking"
    " --disable-component-update --disable-sync --no-first-run --dump-dom";

Result<std::string> read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error(Error::Kind::io, path.string(), "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Status write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!(out << text)) return make_error(Error::Kind::io, path.string(), "cannot be written");
  return {};
}

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

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
        PENUMBRA_TRY_ASSIGN(shaders[*path], read_text(library.root / *path));
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

// JSON inside <script>: "</" would end the element.
std::string script_safe(const std::string& json) {
  std::string out;
  for (std::size_t i = 0; i < json.size(); ++i) {
    out += json[i];
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/') out += '\\';
  }
  return out;
}

// The text of <pre id="result"> in the dumped DOM, unescaped as the DOM
// serializer escapes text.
Result<std::string> result_text(const std::string& dom, const std::string& where) {
  const std::string open = "<pre id=\"result\">";
  const auto begin = dom.find(open);
  const auto end = begin == std::string::npos ? begin : dom.find("</pre>", begin);
  if (end == std::string::npos) {
    return make_error(Error::Kind::internal, where,
                      "the dumped DOM has no <pre id=\"result\">: " + dom.substr(0, 2000));
  }
  const std::string text = dom.substr(begin + open.size(), end - begin - open.size());
  static const std::map<std::string, std::string> kEntities = {
      {"&amp;", "&"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&nbsp;", "\u00a0"}};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    bool replaced = false;
    for (const auto& [entity, character] : kEntities) {
      if (text.compare(i, entity.size(), entity) == 0) {
        out += character;
        i += entity.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) out += text[i++];
  }
  return out;
}

}  // namespace

std::string program_key(const PassFiles& files) {
  return files.vert + "|" + files.frag;
}

Result<nlohmann::json> run_webgl(const Library& library) {
  const fs::path template_path =
      fs::path(PENUMBRA_SOURCE_DIR) / "tests" / "webgl" / "webgl_proof.html";
  PENUMBRA_TRY_ASSIGN(std::string page, read_text(template_path));
  const auto at = page.find(kPlaceholder);
  if (at == std::string::npos) {
    return make_error(Error::Kind::internal, template_path.string(),
                      "has no " + std::string(kPlaceholder));
  }
  PENUMBRA_TRY_ASSIGN(const nlohmann::json input, page_input(library));
  page.replace(at, kPlaceholder.size(), script_safe(input.dump()));

  const fs::path dir =
      fs::path(::testing::TempDir()) / ("penumbra-webgl-" + std::to_string(::getpid()));
  fs::create_directories(dir / "profile");
  const fs::path page_path = dir / "webgl_proof.html";
  PENUMBRA_TRY(write_text(page_path, page));
  const fs::path dom_path = dir / "dom.html";
  const fs::path log_path = dir / "chromium.log";
  const std::string command = "timeout 300 " + shell_quoted(CHROMIUM_EXECUTABLE) + kFlags +
                              " --user-data-dir=" + shell_quoted((dir / "profile").string()) + " " +
                              shell_quoted("file://" + page_path.string()) + " > " +
                              shell_quoted(dom_path.string()) + " 2> " +
                              shell_quoted(log_path.string());
  const int status = std::system(command.c_str());
  const std::string where = page_path.string();
  if (status != 0) {
    auto log = read_text(log_path);
    return make_error(Error::Kind::device, where,
                      "chromium exited with status " + std::to_string(status) + ": " +
                          (log ? log->substr(0, 4000) : std::string("(no log)")));
  }
  PENUMBRA_TRY_ASSIGN(const std::string dom, read_text(dom_path));
  PENUMBRA_TRY_ASSIGN(const std::string text, result_text(dom, where));
  nlohmann::json result = nlohmann::json::parse(text, nullptr, false);
  if (result.is_discarded()) {
    return make_error(Error::Kind::internal, where, "the result is not JSON: " + text);
  }
  std::error_code ignored;
  fs::remove_all(dir, ignored);  // kept when the run fails, for its page and log
  return result;
}

}  // namespace penumbra::testing
