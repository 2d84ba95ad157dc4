#include <regex>
#include <sstream>

#include "penumbra/compiler/targets.hpp"
#include "stages/stages.hpp"

namespace penumbra {
namespace {

// What the harness of shaderlib/forms/function.frag adds to the text:
// its input, output and entry point, and in HLSL SPIRV-Cross's stage structs
// and the globals it copies the stage's inputs into.
bool harness_line(const std::string& line) {
  return line.find("penumbra_harness_") != std::string::npos ||
         line.starts_with("static float4 gl_FragCoord;");
}

// The line that starts the harness's entry point: everything from it on is
// the harness (SPIRV-Cross emits the entry point last).
bool entry_point_line(const std::string& line, bool hlsl) {
  return hlsl ? line == "void frag_main()" : line == "void main()";
}

// SPIRV-Cross guards its loop attributes by whether the compiler knows
// GL_EXT_control_flow_attributes, not whether the shader enabled it, and an
// included file cannot enable it (an #extension precedes all code). The
// GLSL function form drops the guard and its SPIRV_CROSS_* markers, which
// would also be unprefixed names: every driver without the extension
// compiles the passes so too.
constexpr std::string_view kAttributesGuard = "#if defined(GL_EXT_control_flow_attributes)";

// `line` without SPIRV-Cross's control-flow markers.
std::string without_markers(const std::string& line) {
  // Most lines have none; std::regex is slow enough to show in a build.
  if (line.find("SPIRV_CROSS_") == std::string::npos) return line;
  static const std::regex kMarker(R"(\bSPIRV_CROSS_(FLATTEN|BRANCH|UNROLL|LOOP)\b ?)");
  return std::regex_replace(line, kMarker, "");
}

}  // namespace

Status ExtractFunctionStage::process(ShaderJob& job) const {
  if (job.form != ShaderForm::function) return {};
  const bool hlsl = traits(job.target).is_hlsl;
  static const std::regex kExtension(R"(^#extension (\w+) : (require|enable)$)");
  std::istringstream lines(job.text);
  std::string line, out;
  std::vector<std::string> extensions;
  bool in_stage_struct = false, found_entry = false;
  bool in_guard = false;
  while (std::getline(lines, line)) {
    if (!hlsl && line == kAttributesGuard) in_guard = true;
    if (in_guard) {
      in_guard = line != "#endif";
      continue;
    }
    if (!hlsl) {
      const std::string bare = without_markers(line);
      if (bare != line && bare.find_first_not_of(' ') == std::string::npos) continue;
      line = bare;
    }
    std::smatch match;
    if (line.starts_with("#extension ") && std::regex_match(line, match, kExtension)) {
      extensions.push_back(match[1]);
      continue;
    }
    if (line.starts_with("#version") || line.starts_with("precision ")) continue;
    if (line.starts_with("struct SPIRV_Cross_")) in_stage_struct = true;
    if (in_stage_struct) {
      in_stage_struct = line != "};";
      continue;
    }
    if (entry_point_line(line, hlsl)) {
      found_entry = true;
      break;
    }
    if (harness_line(line)) continue;
    // One blank line where the harness's declarations leave several.
    if (line.empty() && (out.empty() || out.ends_with("\n\n"))) continue;
    out += line + "\n";
  }
  static const std::regex kSignature(R"((?:^|\n)(float penumbra_visibility\([^)]*\)))");
  std::smatch signature;
  if (!found_entry || !std::regex_search(out, signature, kSignature)) {
    return make_error(Error::Kind::compile, job.describe(),
                      "the cross-compiled text has no penumbra_visibility() before its entry "
                      "point; the function form cannot be cut from it");
  }
  job.reflection.signature = signature[1];
  job.reflection.extensions = std::move(extensions);
  while (out.ends_with("\n\n")) out.pop_back();
  job.text = std::move(out);
  return {};
}

}  // namespace penumbra
