#include "webgl_check.hpp"

namespace penumbra::testing {
namespace {

// Two stages that disagree on one entry give it both values, which matches
// nothing WebGL reports.
void put(Facts& facts, const std::string& key, const std::string& value) {
  auto [it, inserted] = facts.emplace(key, value);
  if (!inserted && it->second != value) it->second += " | " + value;
}

std::string stages_text(bool vertex, bool fragment) {
  if (vertex && fragment) return "vertex+fragment";
  return vertex ? "vertex" : (fragment ? "fragment" : "no stage");
}

// A sampler2DShadow is the one kind WebGL samples with comparison.
std::string texture_text(const std::string& type, bool comparison) {
  return type + (comparison ? ", comparison" : ", no comparison");
}

std::string input_type(const VertexAttribute& input) {
  if (input.format != "GL_FLOAT") return input.format + " x" + std::to_string(input.components);
  return input.components == 1 ? "float" : "vec" + std::to_string(input.components);
}

bool is_sampler(const std::string& type) {
  return type.find("sampler") != std::string::npos;
}

// A lookup of `name` in the program's `lookups.<kind>`, or -1 when absent.
long long looked_up(const nlohmann::json& program, const char* kind, const std::string& name) {
  const auto& table = program.at("lookups").at(kind);
  return table.contains(name) ? table.at(name).get<long long>() : -1;
}

void check_lookups(const PassReflection& pass, const nlohmann::json& program,
                   std::vector<std::string>& out) {
  auto expect_found = [&](const char* kind, const char* call, const std::string& name) {
    if (looked_up(program, kind, name) < 0)
      out.push_back(std::string(call) + "(\"" + name + "\") finds nothing");
  };
  for (const StageBindings* stage : {&pass.vert, &pass.frag}) {
    for (const BlockBinding& block : stage->blocks) {
      expect_found("blocks", "getUniformBlockIndex", block.name);
      for (const ConstantBinding& m : block.members) {
        expect_found("uniforms", "getUniformIndices", m.name);
      }
    }
    for (const ConstantBinding& u : stage->uniforms) {
      expect_found("uniforms", "getUniformIndices", u.name);
    }
    for (const TextureBinding& t : stage->textures) {
      expect_found("samplers", "getUniformLocation", t.name);
    }
  }
  for (const VertexAttribute& input : pass.vertex_inputs) {
    const long long location = looked_up(program, "attributes", input.name);
    if (!input.location || location != static_cast<long long>(*input.location)) {
      out.push_back("getAttribLocation(\"" + input.name + "\") is " + std::to_string(location));
    }
  }
}

// Every render target and the depth target complete a framebuffer with the
// pass's extensions enabled; EXT_color_buffer_float is listed exactly when
// one of its render targets is incomplete without it.
void check_formats(const PassReflection& pass, const nlohmann::json& browser,
                   std::vector<std::string>& out) {
  const auto& framebuffers = browser.at("framebuffers");
  bool needs_float = false;
  auto check = [&](const std::string& format, bool colour) {
    if (!framebuffers.contains(format)) {
      out.push_back("format " + format + " was not tried");
      return;
    }
    const std::string with = framebuffers.at(format).value("with", "");
    if (with != "FRAMEBUFFER_COMPLETE") out.push_back("format " + format + ": " + with);
    if (colour && framebuffers.at(format).value("without", "") != "FRAMEBUFFER_COMPLETE") {
      needs_float = true;
    }
  };
  for (const RenderTarget& target : pass.render_targets) check(target.format, true);
  if (!pass.depth_target.empty()) check(pass.depth_target, false);

  const std::string float_ext = "EXT_color_buffer_float";
  bool lists_float = false;
  for (const std::string& ext : pass.extensions) {
    lists_float = lists_float || ext == float_ext;
    if (!browser.at("extensions").value(ext, false)) {
      out.push_back("extension " + ext + " is not available");
    }
  }
  if (needs_float != lists_float) {
    out.push_back(float_ext + (needs_float ? " is needed to render the pass's targets, unlisted"
                                           : " is listed, but every target renders without it"));
  }
}

}  // namespace

Facts reflected_facts(const PassReflection& pass) {
  Facts facts;
  std::map<std::string, std::pair<bool, bool>> block_stages;
  std::map<std::string, std::uint32_t> block_sizes;
  for (const bool vertex : {true, false}) {
    const StageBindings& stage = vertex ? pass.vert : pass.frag;
    for (const BlockBinding& block : stage.blocks) {
      auto& stages = block_stages[block.name];
      (vertex ? stages.first : stages.second) = true;
      put(facts, "block " + block.name + " size", std::to_string(block.size) + " bytes");
      for (const ConstantBinding& m : block.members) {
        put(facts, "block " + block.name + " member " + m.name,
            m.type + " at " + (m.offset ? std::to_string(*m.offset) : "-"));
      }
      if (block.binding) put(facts, "block " + block.name + " binding", "present");
    }
    for (const ConstantBinding& u : stage.uniforms) put(facts, "uniform " + u.name, u.type);
    for (const TextureBinding& t : stage.textures) {
      put(facts, "texture " + t.name, texture_text(t.type, t.sampler.state.comparison));
      if (t.binding) put(facts, "texture " + t.name + " binding", "present");
    }
  }
  for (const auto& [name, stages] : block_stages) {
    facts["block " + name] = stages_text(stages.first, stages.second);
  }
  for (const VertexAttribute& input : pass.vertex_inputs) {
    facts["input " + input.name] = "location " +
                                   (input.location ? std::to_string(*input.location) : "-") + ", " +
                                   input_type(input);
  }
  for (const RenderTarget& target : pass.render_targets) {
    facts["output " + target.name] = "location " + std::to_string(target.index);
  }
  return facts;
}

Facts webgl_facts(const nlohmann::json& program) {
  Facts facts;
  std::vector<std::string> block_names;
  for (const auto& block : program.value("blocks", nlohmann::json::array())) {
    const std::string name = block.at("name");
    block_names.push_back(name);
    facts["block " + name] = stages_text(block.at("vertex"), block.at("fragment"));
    facts["block " + name + " size"] = std::to_string(block.at("size").get<long long>()) + " bytes";
  }
  for (const auto& u : program.value("uniforms", nlohmann::json::array())) {
    const std::string name = u.at("name");
    const std::string type = u.at("type");
    const long long block = u.at("block");
    const std::string array = u.at("size") == 1 ? "" : "[" + u.at("size").dump() + "]";
    if (block >= 0 && static_cast<std::size_t>(block) < block_names.size()) {
      facts["block " + block_names[static_cast<std::size_t>(block)] + " member " + name] =
          type + array + " at " + std::to_string(u.at("offset").get<long long>());
    } else if (is_sampler(type)) {
      facts["texture " + name] = texture_text(type + array, type.ends_with("Shadow"));
    } else {
      facts["uniform " + name] = type + array;
    }
  }
  for (const auto& a : program.value("attributes", nlohmann::json::array())) {
    facts["input " + a.at("name").get<std::string>()] =
        "location " + std::to_string(a.at("location").get<long long>()) + ", " +
        a.at("type").get<std::string>();
  }
  // Outputs: only a lookup can see them (getFragDataLocation).
  for (const auto& [name, location] : program.at("lookups").at("outputs").items()) {
    if (location.get<long long>() >= 0) {
      facts["output " + name] = "location " + std::to_string(location.get<long long>());
    }
  }
  return facts;
}

std::vector<std::string> check_pass(const PassReflection& pass, const nlohmann::json& program,
                                    const nlohmann::json& browser) {
  std::vector<std::string> out;
  for (const char* stage : {"vert", "frag"}) {
    if (!program.value(std::string(stage) + "_compiled", false)) {
      out.push_back(std::string(stage) + " " + program.value(stage, "") +
                    " does not compile: " + program.value(std::string(stage) + "_log", ""));
    }
  }
  if (!program.value("linked", false)) {
    out.push_back("the program does not link: " + program.value("link_log", ""));
    return out;
  }
  const Facts reflected = reflected_facts(pass);
  const Facts observed = webgl_facts(program);
  for (const auto& [key, value] : reflected) {
    const auto it = observed.find(key);
    if (it == observed.end()) {
      out.push_back(key + ": in the reflection (" + value + "), not in WebGL");
    } else if (it->second != value) {
      out.push_back(key + ": reflection says " + value + ", WebGL " + it->second);
    }
  }
  for (const auto& [key, value] : observed) {
    if (!reflected.contains(key))
      out.push_back(key + ": in WebGL (" + value + "), not in the reflection");
  }
  check_lookups(pass, program, out);
  check_formats(pass, browser, out);
  return out;
}

}  // namespace penumbra::testing
