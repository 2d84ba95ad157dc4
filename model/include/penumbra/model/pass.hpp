// The passes of the shadow pipeline and the stages of a pass.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace penumbra {

// A pass of the shadow pipeline; each is a vertex + fragment pair.
enum class PassKind {
  depth,          // the shadow map (the whitepaper's step 1)
  minmax_init,    // min-max mip level 1 from the map (Dmitriev 2007)
  minmax_reduce,  // min-max mip level l + 1 from level l
  query,          // a technique's visibility per receiver (screen_blur: the unblurred factor)
  blur_h,         // screen_blur: horizontal Gaussian blur of the factor buffer
  blur_v,         // screen_blur: vertical Gaussian blur
  composite,      // screen_blur: a scene colour times the blurred factor
  // The deferred mask: the query's visibility at receivers rebuilt from an
  // engine's camera depth buffer and matrices, in the query's place.
  deferred,
};
inline constexpr std::array kAllPassKinds = {
    PassKind::depth,  PassKind::minmax_init, PassKind::minmax_reduce, PassKind::query,
    PassKind::blur_h, PassKind::blur_v,      PassKind::composite,     PassKind::deferred};
std::string_view to_string(PassKind pass);
std::optional<PassKind> parse_pass(std::string_view name);

// The forms a variant is built in, each for a kind of engine
// (docs/engines/README.md): the query pass (with screen_blur's blur and
// composite passes), the deferred mask (docs/deferred-mask.md) and the
// function form (docs/function-form.md). Any form brings the passes it reads:
// the depth pass and, for the min-max techniques, the min-max chain.
enum class Form { query, deferred, function };
inline constexpr std::array kAllForms = {Form::query, Form::deferred, Form::function};
std::string_view to_string(Form form);
std::optional<Form> parse_form(std::string_view name);
// "query, function": `forms`' names joined, for messages.
std::string to_string(std::span<const Form> forms);
// "query, deferred, function": the allowed names, for messages.
std::string allowed_forms();

enum class ShaderStage { vertex, fragment };
inline constexpr std::array kAllStages = {ShaderStage::vertex, ShaderStage::fragment};
std::string_view to_string(ShaderStage stage);
// index.json's name of a stage: "vert" or "frag".
std::string_view stage_key(ShaderStage stage);

}  // namespace penumbra
