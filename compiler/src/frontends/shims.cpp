#include "frontends/shims.hpp"

#include <array>

namespace penumbra {
namespace {

struct Shim {
  Target target;
  std::string_view name;
  Result<std::string> (*apply)(std::string_view text);
};

// Every shim, applied in this order to the texts of its target.
constexpr std::array kShims = {
    Shim{Target::essl300, "essl300-version-310", &essl300_version_as_310},
    Shim{Target::hlsl_dx9, "dx9-output-semantics-as-sv", &dx9_output_semantics_as_system_values},
};

// Replaces every `from` in `text` with `to`.
void replace_all(std::string& text, std::string_view from, std::string_view to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
    text.replace(at, from.size(), to);
    at += to.size();
  }
}

}  // namespace

Result<std::string> essl300_version_as_310(std::string_view text) {
  // The emitter writes the version first, as ESSL requires; anything else
  // is not an emitted text and is left to fail rather than be guessed at.
  constexpr std::string_view from = "#version 300 es\n";
  if (!text.starts_with(from)) {
    return make_error(Error::Kind::compile, "",
                      "essl300-version-310: the text does not begin with '#version 300 es'");
  }
  return "#version 310 es\n" + std::string(text.substr(from.size()));
}

Result<std::string> dx9_output_semantics_as_system_values(std::string_view text) {
  constexpr std::string_view open = "struct SPIRV_Cross_Output\n{\n";
  const std::size_t begin = text.find(open);
  if (begin == std::string_view::npos) return std::string(text);  // no outputs to rename
  const std::size_t end = text.find("\n};", begin);
  if (end == std::string_view::npos) {
    return make_error(Error::Kind::compile, "",
                      "dx9-output-semantics-as-sv: struct SPIRV_Cross_Output is not closed");
  }
  std::string members(text.substr(begin, end - begin));
  replace_all(members, " : POSITION;", " : SV_Position;");
  replace_all(members, " : DEPTH;", " : SV_Depth;");
  return std::string(text.substr(0, begin)) + members + std::string(text.substr(end));
}

Result<ShimmedText> apply_shims(Target target, std::string_view text) {
  ShimmedText out{std::string(text), {}};
  for (const Shim& shim : kShims) {
    if (shim.target != target) continue;
    auto rewritten = shim.apply(out.text);
    if (!rewritten) return rewritten.error();
    if (*rewritten == out.text) continue;  // nothing to rewrite in this text
    out.text = std::move(*rewritten);
    out.shims.emplace_back(shim.name);
  }
  return out;
}

}  // namespace penumbra
