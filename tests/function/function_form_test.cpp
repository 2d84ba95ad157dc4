// The function form (docs/function-form.md): for every default variant that
// has one and every text target, index.json names the file, its signature
// and bindings; the file declares nothing without the penumbra_ prefix; and
// an engine-like shader that includes it, declares the unprefixed twin of
// every name in it and calls penumbra_visibility() compiles with the real
// compiler of its API.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "default_library.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/compiler/stage.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/compiler/text_frontend.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/model/target_traits.hpp"
#include "penumbra/support/file.hpp"
#include "vkd3d/run_vkd3d.hpp"

namespace penumbra::testing {
namespace {

using ::testing::StartsWith;

std::vector<std::string> function_variants() {
  std::vector<std::string> out;
  for (const Variant& variant : default_variants()) {
    if (has_function_form(variant.technique)) out.push_back(variant.name);
  }
  return out;
}

// The names the text declares at file scope: for each top-level statement
// (layout qualifiers removed), the last identifier before its first
// `(`, `[`, `=`, `:`, `;` or `{`.
std::vector<std::string> file_scope_names(const std::string& text) {
  static const std::regex kComment(R"(//[^\n]*)");
  static const std::regex kLayout(R"(layout\([^)]*\))");
  const std::string code = std::regex_replace(std::regex_replace(text, kComment, ""), kLayout, "");
  std::vector<std::string> names;
  int depth = 0;
  bool named = false;  // the current statement's name is taken
  std::string statement;
  for (char c : code) {
    if (depth == 0 && !named && std::string_view("([=:;{").find(c) != std::string_view::npos) {
      static const std::regex kLast(R"((\w+)\s*$)");
      std::smatch last;
      if (std::regex_search(statement, last, kLast)) names.push_back(last[1]);
      named = true;
    }
    if (c == '{' || c == '(') ++depth;
    if (c == '}' || c == ')') --depth;
    statement += c;
    if (depth == 0 && (c == ';' || c == '}')) {
      statement.clear();
      named = false;
    }
  }
  return names;
}

// An engine's own declarations: the unprefixed twin of every penumbra_ name.
std::string engine_names(const std::string& text, bool hlsl) {
  static const std::regex kPrefixed(R"(\bpenumbra_(\w+))");
  std::set<std::string> twins;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kPrefixed);
       it != std::sregex_iterator(); ++it) {
    twins.insert((*it)[1]);
  }
  std::string out = "// The engine's own names\n";
  for (const std::string& twin : twins) out += (hlsl ? "static float " : "float ") + twin + ";\n";
  return out;
}

// A fragment shader of `target` that includes `text` as an engine would.
std::string engine_shader(Target target, const PassReflection& reflection,
                          const std::string& text) {
  const bool hlsl = traits(target).is_hlsl;
  const bool pixel = reflection.signature.find("pixel") != std::string::npos;
  // An atlas or array variant's light, each call's: the whitepaper's light
  // in the atlas's first quarter, or the array's layer 2 (constants a
  // compiler folds: no 0 / 0 anywhere).
  const std::string vec4 = hlsl ? "float4" : "vec4";
  const std::string whitepaper =
      ", " + vec4 + "(0.5, 3.75, 9.5, 0.125), " + vec4 + "(0.01, 0.05, 0.03125, 32.0), ";
  const std::string light =
      reflection.signature.find("map_tile") != std::string::npos
          ? whitepaper + vec4 + "(0.0, 0.0, 0.5, 0.5)"
          : (reflection.signature.find("map_layer") != std::string::npos ? whitepaper + "2" : "");
  std::string out;
  if (!hlsl) {
    out = target == Target::glsl450   ? "#version 450\n"
          : target == Target::glsl330 ? "#version 330\n"
                                      : "#version 300 es\nprecision highp float;\n";
    for (const std::string& extension : reflection.extensions) {
      out += "#extension " + extension + " : require\n";
    }
    out += engine_names(text, false) + text;
    // Input locations need GLSL 4.10; 3.30 and ES 3.00 match inputs by name.
    out += target == Target::glsl450 ? "\nlayout(location = 0) in" : "\nin";
    out += " vec4 light_clip_position;\n";
    out += "layout(location = 0) out vec4 colour;\n";
    out += "void main() {\n  colour = vec4(penumbra_visibility(light_clip_position";
    out += std::string(pixel ? ", floor(gl_FragCoord.xy)" : "") + light + "));\n}\n";
    return out;
  }
  const bool sm3 = traits(target).shader_model == 3;
  out = engine_names(text, true) + text;
  out += "\nfloat4 main(float4 light_clip_position : TEXCOORD0, float4 position : ";
  out += sm3 ? "VPOS) : COLOR0 {\n" : "SV_Position) : SV_Target {\n";
  out += "  return penumbra_visibility(light_clip_position";
  out += std::string(pixel ? ", floor(position.xy)" : "") + light + ").xxxx;\n}\n";
  return out;
}

class FunctionFormTest : public ::testing::TestWithParam<std::string> {};

TEST_P(FunctionFormTest, IndexNamesAPrefixedFileThatCompilesInAnEngineShader) {
  auto built = build_default_variant(GetParam());
  ASSERT_TRUE(built.ok()) << built.error().to_string();
  const Library& library = (*built)->library();
  const LibraryVariant& read = library.variants.at(0);
  for (Target target : read.variant.targets) {
    SCOPED_TRACE(std::string(to_string(target)));
    const auto found = read.function.find(target);
    if (!traits(target).is_text) {
      EXPECT_EQ(found, read.function.end()) << "SPIR-V has no includable form";
      continue;
    }
    ASSERT_NE(found, read.function.end());
    const FunctionForm& form = found->second;
    const PassReflection& reflection = form.reflection;
    const bool hlsl = traits(target).is_hlsl;
    const bool rotation = read.variant.keys.rotation.has_value();
    const std::string vec4 = hlsl ? "float4" : "vec4";
    const std::string vec2 = hlsl ? "float2" : "vec2";
    const MapLayout layout = map_layout(read.variant.keys);
    const std::string per_call = ", " + vec4 + " light, " + vec4 + " sampling, ";
    EXPECT_EQ(reflection.signature, "float penumbra_visibility(" + vec4 + " light_clip_position" +
                                        (rotation ? ", " + vec2 + " pixel" : "") +
                                        (layout == MapLayout::atlas ? per_call + vec4 + " map_tile"
                                         : layout == MapLayout::array ? per_call + "int map_layer"
                                                                      : "") +
                                        ")");
    const Result<std::string> text = read_file(library.root / form.file);
    ASSERT_TRUE(text.ok()) << text.error().to_string();
    EXPECT_NE(text->find(reflection.signature), std::string::npos);

    for (const std::string& name : file_scope_names(*text)) {
      EXPECT_THAT(name, ::testing::AnyOf(StartsWith("penumbra_"), StartsWith("_penumbra_")))
          << form.file;
    }
    for (const TextureBinding& texture : reflection.frag.textures) {
      EXPECT_THAT(texture.name, StartsWith("penumbra_"));
      EXPECT_NE(text->find(texture.name), std::string::npos) << texture.name;
    }
    for (const ConstantBinding& uniform : reflection.frag.uniforms) {
      EXPECT_THAT(uniform.name, StartsWith("penumbra_"));
    }
    for (const BlockBinding& block : reflection.frag.blocks) {
      EXPECT_EQ(block.name, "penumbra_ShadowParams");
    }

    const std::string shader = engine_shader(target, reflection, *text);
    if (!hlsl) {
      auto compiled = compile_target_text(target, ShaderStage::fragment, shader, form.file);
      EXPECT_TRUE(compiled.ok()) << compiled.error().to_string() << "\n" << shader;
      continue;
    }
    auto compiler = recorded_hlsl_compiler();
    ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
    const std::filesystem::path source = library.root / (form.file + ".engine.hlsl");
    ASSERT_TRUE(write_file(source, shader).ok());
    const std::optional<BytecodeFormat> format = bytecode_format(target, ShaderStage::fragment);
    ASSERT_TRUE(format.has_value());
    const std::string& profile = format->profile;
    auto run =
        run_vkd3d(*compiler,
                  {"-x", "hlsl", "-p", profile, "-b", std::string(format->vkd3d_type), "-e", "main",
                   "-o", source.string() + std::string(format->extension), source.string()},
                  std::chrono::seconds(120));
    ASSERT_TRUE(run.ok()) << run.error().to_string();
    EXPECT_EQ(run->exit_code, 0) << profile << ":\n" << run->output << "\n" << shader;
  }
}

INSTANTIATE_TEST_SUITE_P(Default, FunctionFormTest, ::testing::ValuesIn(function_variants()),
                         [](const auto& param_info) { return test_name(param_info.param); });

// Every technique but screen_blur, which blurs after its query, has a
// function form and a deferred pass, the back-projections too.
TEST(FunctionFormTest, EveryTechniqueButTheBlurHasOne) {
  for (const char* name : {"backprojection", "bitmask_backprojection_bits64", "minmax_pcf_k8"}) {
    auto built = build_default_variant(name, {Target::glsl450});
    ASSERT_TRUE(built.ok()) << built.error().to_string();
    EXPECT_TRUE((*built)->library().variants.at(0).function.contains(Target::glsl450)) << name;
    EXPECT_TRUE((*built)->library().variants.at(0).passes.contains(PassKind::deferred)) << name;
  }
  for (Technique technique : kAllTechniques) {
    EXPECT_EQ(has_function_form(technique), technique != Technique::screen_blur)
        << to_string(technique);
  }
}

}  // namespace
}  // namespace penumbra::testing
