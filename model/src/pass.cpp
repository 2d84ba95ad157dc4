#include "penumbra/model/pass.hpp"

#include <cstddef>

namespace penumbra {
namespace {

// Indexed by the enum values, in declaration order.
constexpr std::array<std::string_view, kAllPassKinds.size()> kPassNames = {
    "depth", "minmax_init", "minmax_reduce", "query", "blur_h", "blur_v", "composite", "deferred"};
constexpr std::array<std::string_view, kAllForms.size()> kFormNames = {"query", "deferred",
                                                                       "function"};

}  // namespace

std::string_view to_string(PassKind pass) {
  return kPassNames[static_cast<std::size_t>(pass)];
}

std::optional<PassKind> parse_pass(std::string_view name) {
  for (std::size_t i = 0; i < kPassNames.size(); ++i) {
    if (kPassNames[i] == name) return kAllPassKinds[i];
  }
  return std::nullopt;
}

std::string_view to_string(Form form) {
  return kFormNames[static_cast<std::size_t>(form)];
}

std::optional<Form> parse_form(std::string_view name) {
  for (std::size_t i = 0; i < kFormNames.size(); ++i) {
    if (kFormNames[i] == name) return kAllForms[i];
  }
  return std::nullopt;
}

std::string to_string(std::span<const Form> forms) {
  std::string out;
  for (Form form : forms) out += (out.empty() ? "" : ", ") + std::string(to_string(form));
  return out;
}

std::string allowed_forms() {
  return to_string(kAllForms);
}

std::string_view to_string(ShaderStage stage) {
  return stage == ShaderStage::vertex ? "vertex" : "fragment";
}

std::string_view stage_key(ShaderStage stage) {
  return stage == ShaderStage::vertex ? "vert" : "frag";
}

}  // namespace penumbra
