// Proves the essl300 reflection by glslang's OpenGL ES 3.00 front end (the
// text's `#version 300 es`, no client API, none of the compiler's
// settings): per stage, the uniform block (its name, that the text gives it
// no binding, its std140 size, every member as GL names it,
// "ShadowParams.light", with its offset and type), the sampler uniforms
// (name, type, comparison, and that the text gives them no binding: ES 3.00
// has no binding layout, so the reflection must carry none), the vertex
// inputs (location, components) and the fragment outputs (location).
#include "glslang_reflect.hpp"
#include "proof.hpp"

namespace penumbra::testing {
namespace {

constexpr FactStyle kStyle{};

// A glslang binding or location, -1 where the text gives none.
std::optional<std::uint32_t> index_or_none(int binding) {
  if (binding < 0) return std::nullopt;
  return static_cast<std::uint32_t>(binding);
}

void observed_stage(ShaderStage stage, const GlslangReflection& text, Facts& facts) {
  const std::string key(stage_key(stage));
  for (const GlslangBlock& block : text.blocks) {
    facts[key + " block " + block.name] =
        slot_text(kStyle, std::nullopt, index_or_none(block.binding)) + ", " +
        std::to_string(block.size) + " bytes";
  }
  for (const GlslangObject& uniform : text.uniforms) {
    if (uniform.block >= 0) {
      facts[key + " block " + text.blocks[static_cast<std::size_t>(uniform.block)].name +
            " member " + uniform.name] =
          member_text(kStyle, uniform.type, static_cast<std::uint32_t>(uniform.offset), 0);
    } else if (uniform.type.starts_with("sampler")) {
      facts[key + " texture " + uniform.name] =
          slot_text(kStyle, std::nullopt, index_or_none(uniform.binding)) + ", " +
          texture_text(uniform.type, uniform.type.ends_with("Shadow"));
    } else if (uniform.live) {
      facts[key + " uniform " + uniform.name] = uniform.type;
    }
  }
  if (stage == ShaderStage::vertex) {
    for (const GlslangObject& input : text.inputs) {
      if (input.name.starts_with("gl_")) continue;  // built-ins: nothing to bind
      facts["vert input " + input.name] = input_text(
          index_or_none(input.location), static_cast<std::uint32_t>(input.components),
          input.type.starts_with("vec") || input.type == "float" ? "GL_FLOAT" : input.type);
    }
  } else {
    for (const GlslangObject& output : text.outputs) {
      if (output.name.starts_with("gl_")) continue;  // gl_FragDepth: no render target
      facts["frag output " + output.name] = "location " + std::to_string(output.location);
    }
  }
}

}  // namespace

Status prove_glslang_essl(const Library& library, const LibraryVariant& variant, PassKind pass,
                          Target target) {
  PENUMBRA_TRY_ASSIGN(const PassReflection* reflection, reflection_of(variant, pass, target));
  Facts observed;
  for (const ShaderStage stage : {ShaderStage::vertex, ShaderStage::fragment}) {
    PENUMBRA_TRY_ASSIGN(const std::string text,
                        read_pass_file(library, variant, pass, target, stage));
    auto parsed = glslang_reflect(text, stage, GlslangSource::glsl);
    if (!parsed) {
      return proof_error(variant, pass, target,
                         std::string(stage_key(stage)) + ": " + parsed.error().to_string());
    }
    observed_stage(stage, *parsed, observed);
  }
  return compare_facts(variant, pass, target, "glslang (ESSL 3.00)",
                       reflected_facts(*reflection, kStyle), observed);
}

}  // namespace penumbra::testing
