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

std::string binding_text(std::optional<std::uint32_t> binding) {
  return "binding " + (binding ? std::to_string(*binding) : std::string("-"));
}

std::string binding_text(int binding) {
  return "binding " + (binding >= 0 ? std::to_string(binding) : std::string("-"));
}

std::string texture_text(std::string_view type, bool comparison) {
  return std::string(type) + (comparison ? ", comparison" : ", no comparison");
}

std::string input_text(int location, int components, std::string_view format) {
  return "location " + std::to_string(location) + ", " + std::to_string(components) +
         " components, " + std::string(format);
}

void reflected_stage(std::string_view stage, const StageBindings& bindings, Facts& facts) {
  for (const BlockBinding& block : bindings.blocks) {
    const std::string key = std::string(stage) + " block " + block.name;
    facts[key] = binding_text(block.binding) + ", " + std::to_string(block.size) + " bytes";
    for (const ConstantBinding& member : block.members) {
      facts[key + " member " + member.name] =
          member.type + " at " + (member.offset ? std::to_string(*member.offset) : "-");
    }
  }
  for (const ConstantBinding& uniform : bindings.uniforms) {
    facts[std::string(stage) + " uniform " + uniform.name] = uniform.type;
  }
  for (const TextureBinding& texture : bindings.textures) {
    facts[std::string(stage) + " texture " + texture.name] =
        binding_text(texture.binding) + ", " +
        texture_text(texture.type, texture.sampler.state.comparison);
  }
}

Facts reflected(const PassReflection& pass) {
  Facts facts;
  reflected_stage("vert", pass.vert, facts);
  reflected_stage("frag", pass.frag, facts);
  for (const VertexAttribute& input : pass.vertex_inputs) {
    facts["vert input " + input.name] =
        input_text(input.location ? static_cast<int>(*input.location) : -1,
                   static_cast<int>(input.components), input.format);
  }
  for (const RenderTarget& target : pass.render_targets) {
    facts["frag output " + target.name] = "location " + std::to_string(target.index);
  }
  return facts;
}

void observed_stage(ShaderStage stage, const GlslangReflection& text, Facts& facts) {
  const std::string key(stage_key(stage));
  for (const GlslangBlock& block : text.blocks) {
    facts[key + " block " + block.name] =
        binding_text(block.binding) + ", " + std::to_string(block.size) + " bytes";
  }
  for (const GlslangObject& uniform : text.uniforms) {
    if (uniform.block >= 0) {
      facts[key + " block " + text.blocks[static_cast<std::size_t>(uniform.block)].name +
            " member " + uniform.name] = uniform.type + " at " + std::to_string(uniform.offset);
    } else if (uniform.type.starts_with("sampler")) {
      facts[key + " texture " + uniform.name] =
          binding_text(uniform.binding) + ", " +
          texture_text(uniform.type, uniform.type.ends_with("Shadow"));
    } else if (uniform.live) {
      facts[key + " uniform " + uniform.name] = uniform.type;
    }
  }
  if (stage == ShaderStage::vertex) {
    for (const GlslangObject& input : text.inputs) {
      if (input.name.starts_with("gl_")) continue;  // built-ins: nothing to bind
      facts["vert input " + input.name] = input_text(
          input.location, input.components,
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
  return compare_facts(variant, pass, target, "glslang (ESSL 3.00)", reflected(*reflection),
                       observed);
}

}  // namespace penumbra::testing
