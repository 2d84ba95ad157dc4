#include "glsl/glslang_setup.hpp"

#include <mutex>
#include <optional>
#include <regex>
#include <utility>

namespace penumbra {
namespace {

struct GlslangProcess {
  GlslangProcess() { glslang::InitializeProcess(); }
  ~GlslangProcess() { glslang::FinalizeProcess(); }
};

}  // namespace

void ensure_glslang_initialized() {
  static GlslangProcess process;
}

EShLanguage glslang_stage(ShaderStage stage) {
  return stage == ShaderStage::vertex ? EShLangVertex : EShLangFragment;
}

void configure_environment(glslang::TShader& shader, ShaderStage stage) {
  shader.setEnvInput(glslang::EShSourceGlsl, glslang_stage(stage), glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
}

glslang::TShader::Includer::IncludeResult* ShaderlibIncluder::includeLocal(
    const char* header_name, const char* /*includer_name*/, size_t /*inclusion_depth*/) {
  std::string_view name(header_name);
  if (name == "variant.glsl") {
    return new IncludeResult(header_name, variant_header_.data(), variant_header_.size(), nullptr);
  }
  auto text = source_.read(name);
  if (!text) return nullptr;  // glslang reports the missing include with its location
  read_.emplace_back(name);
  auto* owned = new std::string(std::move(*text));
  return new IncludeResult(header_name, owned->data(), owned->size(), owned);
}

glslang::TShader::Includer::IncludeResult* ShaderlibIncluder::includeSystem(
    const char* header_name, const char* includer_name, size_t inclusion_depth) {
  return includeLocal(header_name, includer_name, inclusion_depth);
}

void ShaderlibIncluder::releaseInclude(IncludeResult* result) {
  if (result) delete static_cast<std::string*>(result->userData);
  delete result;
}

namespace {

// A name glslang gives a place: a shaderlib path (the pass, an include),
// "variant.glsl" (generated, no file), or a source-string number (the pass).
std::string place_location(const ShaderlibSource& source, std::string_view name,
                           std::string_view pass) {
  if (name == "variant.glsl") return "<generated variant.glsl>";
  if (!name.empty() && name.find_first_not_of("0123456789") == std::string_view::npos) {
    return source.location(pass);
  }
  return source.location(name);
}

// The text of the token a message is about: the quoted one ("'x' :
// undeclared identifier"), or for a syntax error the punctuation glslang's
// grammar names ("'' : syntax error, unexpected SEMICOLON").
std::string_view offending_token(std::string_view message) {
  if (message.size() < 3 || message[0] != '\'') return {};
  const std::size_t close = message.find("' : ", 1);
  if (close == std::string_view::npos) return {};
  if (close > 1) return message.substr(1, close - 1);
  static constexpr std::pair<std::string_view, std::string_view> kPunctuation[] = {
      {"SEMICOLON", ";"},    {"COMMA", ","},         {"COLON", ":"},      {"EQUAL", "="},
      {"LEFT_PAREN", "("},   {"RIGHT_PAREN", ")"},   {"LEFT_BRACE", "{"}, {"RIGHT_BRACE", "}"},
      {"LEFT_BRACKET", "["}, {"RIGHT_BRACKET", "]"}, {"DOT", "."},        {"QUESTION", "?"}};
  constexpr std::string_view kUnexpected = "unexpected ";
  const std::size_t at = message.find(kUnexpected);
  if (at == std::string_view::npos) return {};
  std::string_view name = message.substr(at + kUnexpected.size());
  name = name.substr(0, name.find_first_of(", "));
  for (const auto& [grammar, text] : kPunctuation) {
    if (name == grammar) return text;
  }
  return {};
}

// glslang gives no column; the offending token's first place on the line
// stands in for it. Empty when the file, the line or the token is unknown.
std::string column(const ShaderlibSource& source, std::string_view name, std::string_view pass,
                   std::string_view line_number, std::string_view message) {
  const std::string_view token = offending_token(message);
  if (token.empty() || name == "variant.glsl") return "";
  const bool numbered = name.find_first_not_of("0123456789") == std::string_view::npos;
  const std::optional<std::string> text = source.read(numbered ? pass : name);
  if (!text) return "";
  std::size_t begin = 0;
  for (long line = std::stol(std::string(line_number)); line > 1 && begin != std::string::npos;
       --line) {
    begin = text->find('\n', begin);
    if (begin != std::string::npos) ++begin;
  }
  if (begin == std::string::npos) return "";
  const std::string_view line =
      std::string_view(*text).substr(begin, text->find('\n', begin) - begin);
  const std::size_t at = line.find(token);
  return at == std::string_view::npos ? "" : ":" + std::to_string(at + 1);
}

}  // namespace

Error glslang_error(const ShaderlibSource& source, const std::string& context,
                    std::string_view heading, std::string_view log, std::string_view pass) {
  // "ERROR: techniques/pcss.glsl:12: 'x' : undeclared identifier"; the
  // place becomes "LOCATION:12:COL".
  static const std::regex kMessage(R"(^(ERROR|WARNING): (.+):([0-9]+): (.*)$)");
  static const std::regex kSummary(R"(^ERROR: [0-9]+ compilation errors\..*$)");
  std::optional<std::string> where;
  std::string message(heading);
  std::string rest;
  std::size_t begin = 0;
  while (begin < log.size()) {
    std::size_t end = log.find('\n', begin);
    if (end == std::string_view::npos) end = log.size();
    const std::string line(log.substr(begin, end - begin));
    begin = end + 1;
    std::smatch match;
    if (line.empty() || std::regex_match(line, kSummary)) continue;
    if (!std::regex_match(line, match, kMessage)) {
      rest += "\n" + line;
      continue;
    }
    const std::string place = place_location(source, match[2].str(), pass) + ":" + match[3].str() +
                              column(source, match[2].str(), pass, match[3].str(), match[4].str());
    if (!where && match[1] == "ERROR") {
      where = place;
      message += match[4].str();
    } else {
      rest +=
          "\n" + place + ": " + (match[1] == "ERROR" ? "error: " : "warning: ") + match[4].str();
    }
  }
  if (!where) {
    return make_error(Error::Kind::compile, context,
                      std::string(heading) + "\n" + std::string(log));
  }
  return make_error(Error::Kind::compile, *where + ": " + context, message + rest);
}

}  // namespace penumbra
