// Proves the HLSL targets' reflections by glslang's HLSL front end (entry
// "main"; EShMsgHlslDX9Compatible for the d3d9 dialect; no binding shifts, no
// automatic mapping), which reads a register(X#) as binding # and a DX9
// register(cN) global as the member of $Global at offset 16 * N:
//  - d3d10 (hlsl_dx10): each cbuffer's b#, size and member offsets and types; each
//    Texture2D's t#; each SamplerState / SamplerComparisonState's s# and
//    whether it compares;
//  - d3d9 (hlsl_dx9): each constant's c# (its $Global offset / 16) and register
//    count, gl_HalfPixel's in vertex shaders; each sampler2D's s#;
//  - both: the vertex inputs' semantics and components, the fragment
//    outputs' render targets (COLOR# / SV_Target#).
// glslang keeps no register letter, so the letter is the one the declared
// type takes (b for cbuffers, t for textures, s for samplers, c for
// constants) and the reflection's must match it.
#include <cctype>

#include "glslang_reflect.hpp"
#include "penumbra/model/target_traits.hpp"
#include "proof.hpp"

namespace penumbra::testing {
namespace {

std::string hlsl_type(const std::string& glslang_type) {
  if (glslang_type.starts_with("vec")) return "float" + glslang_type.substr(3);
  return glslang_type;
}

std::string sampler_text(std::string_view reg, std::string_view type, bool comparison) {
  return std::string(reg) + ", " + std::string(type) +
         (comparison ? ", comparison" : ", no comparison");
}

std::string input_text(std::string_view semantic, std::uint32_t components,
                       std::string_view format) {
  return std::string(semantic) + ", " + std::to_string(components) + " components, " +
         std::string(format);
}

constexpr std::string_view kDxgiFloats[] = {"DXGI_FORMAT_R32_FLOAT", "DXGI_FORMAT_R32G32_FLOAT",
                                            "DXGI_FORMAT_R32G32B32_FLOAT",
                                            "DXGI_FORMAT_R32G32B32A32_FLOAT"};
constexpr std::string_view kD3d9Floats[] = {"D3DDECLTYPE_FLOAT1", "D3DDECLTYPE_FLOAT2",
                                            "D3DDECLTYPE_FLOAT3", "D3DDECLTYPE_FLOAT4"};

void reflected_stage(std::string_view stage, const StageBindings& bindings, Facts& facts) {
  for (const BlockBinding& block : bindings.blocks) {
    const std::string key = std::string(stage) + " block " + block.name;
    facts[key] = block.reg + ", " + std::to_string(block.size) + " bytes";
    for (const ConstantBinding& member : block.members) {
      facts[key + " member " + member.name] =
          member.type + " at " + (member.offset ? std::to_string(*member.offset) : "-");
    }
  }
  for (const ConstantBinding& constant : bindings.uniforms) {
    facts[std::string(stage) + " constant " + constant.name] =
        constant.reg + ", spans " + std::to_string(constant.registers) + ", " + constant.type;
  }
  for (const TextureBinding& texture : bindings.textures) {
    const SamplerBinding& sampler = texture.sampler;
    facts[std::string(stage) + " texture " + texture.name] =
        sampler_text(texture.reg, texture.type, sampler.name.empty() && sampler.state.comparison);
    if (!sampler.name.empty()) {
      facts[std::string(stage) + " sampler " + sampler.name] =
          sampler_text(sampler.reg, sampler.type, sampler.state.comparison);
    }
  }
}

Facts reflected(const PassReflection& pass) {
  Facts facts;
  reflected_stage("vert", pass.vert, facts);
  reflected_stage("frag", pass.frag, facts);
  for (const VertexAttribute& input : pass.vertex_inputs) {
    facts["vert input " + input.name] = input_text(input.semantic, input.components, input.format);
  }
  for (const RenderTarget& target : pass.render_targets) {
    facts["frag output " + target.name] = "render target " + std::to_string(target.index);
  }
  return facts;
}

// "stage_input.position" -> "position": glslang names entry-point struct
// members through their parameter.
std::string member_name(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos ? name : name.substr(dot + 1);
}

// The render target of an output semantic ("SV_Target0", "COLOR0"), or -1.
int render_target(std::string semantic) {
  for (char& c : semantic) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (std::string_view prefix : {"SV_TARGET", "COLOR"}) {
    if (semantic.starts_with(prefix)) {
      const std::string index = semantic.substr(prefix.size());
      return index.empty() ? 0 : std::stoi(index);
    }
  }
  return -1;
}

void observed_stage(ShaderStage stage, Target target, const GlslangReflection& text, Facts& facts) {
  const std::string key(stage_key(stage));
  const bool dx9 = traits(target).dialect == ReflectionDialect::d3d9;
  for (const GlslangBlock& block : text.blocks) {
    // DX9's loose constants: glslang's $Global, one register per 16 bytes.
    if (dx9 && block.name == "$Global") continue;
    facts[key + " block " + block.name] =
        "b" + std::to_string(block.binding) + ", " + std::to_string(block.size) + " bytes";
  }
  for (const GlslangObject& uniform : text.uniforms) {
    const std::string& type = uniform.type;
    const std::string binding = std::to_string(uniform.binding);
    if (uniform.block >= 0) {
      const GlslangBlock& block = text.blocks[static_cast<std::size_t>(uniform.block)];
      if (dx9 && block.name == "$Global") {
        const bool aligned = uniform.offset % 16 == 0 && uniform.components <= 4;
        facts[key + " constant " + uniform.name] =
            (aligned ? "c" + std::to_string(uniform.offset / 16)
                     : "offset " + std::to_string(uniform.offset)) +
            ", spans 1, " + hlsl_type(type);
      } else {
        facts[key + " block " + block.name + " member " + uniform.name] =
            hlsl_type(type) + " at " + std::to_string(uniform.offset);
      }
    } else if (type == "sampler2D" || type == "sampler2DShadow") {  // DX9
      facts[key + " texture " + uniform.name] =
          sampler_text("s" + binding, "sampler2D", type == "sampler2DShadow");
    } else if (type.starts_with("texture2D")) {
      const bool array = type.starts_with("texture2DArray");
      facts[key + " texture " + uniform.name] =
          sampler_text("t" + binding, array ? "Texture2DArray" : "Texture2D", false);
    } else if (type == "sampler" || type == "samplerShadow") {
      const bool comparison = type == "samplerShadow";
      facts[key + " sampler " + uniform.name] = sampler_text(
          "s" + binding, comparison ? "SamplerComparisonState" : "SamplerState", comparison);
    } else {
      facts[key + " uniform " + uniform.name] = type;
    }
  }
  if (stage == ShaderStage::vertex) {
    for (const GlslangObject& input : text.inputs) {
      const auto components = static_cast<std::uint32_t>(input.components);
      const bool floats = input.type.starts_with("vec") || input.type == "float";
      const std::string_view format = !floats || components == 0 || components > 4
                                          ? std::string_view(input.type)
                                          : (dx9 ? kD3d9Floats : kDxgiFloats)[components - 1];
      facts["vert input " + member_name(input.name)] =
          input_text(input.semantic, components, format);
    }
  } else {
    for (const GlslangObject& output : text.outputs) {
      const int index = render_target(output.semantic);
      if (index < 0) continue;  // SV_Depth and the like are no render target
      facts["frag output " + member_name(output.name)] = "render target " + std::to_string(index);
    }
  }
}

}  // namespace

Status prove_glslang_hlsl(const Library& library, const LibraryVariant& variant, PassKind pass,
                          Target target) {
  PENUMBRA_TRY_ASSIGN(const PassReflection* reflection, reflection_of(variant, pass, target));
  const GlslangSource source = traits(target).dialect == ReflectionDialect::d3d9
                                   ? GlslangSource::hlsl_dx9
                                   : GlslangSource::hlsl;
  Facts observed;
  for (const ShaderStage stage : {ShaderStage::vertex, ShaderStage::fragment}) {
    PENUMBRA_TRY_ASSIGN(const std::string text,
                        read_pass_file(library, variant, pass, target, stage));
    auto parsed = glslang_reflect(text, stage, source);
    if (!parsed) {
      return proof_error(variant, pass, target,
                         std::string(stage_key(stage)) + ": " + parsed.error().to_string());
    }
    observed_stage(stage, target, *parsed, observed);
  }
  return compare_facts(variant, pass, target, "glslang (HLSL)", reflected(*reflection), observed);
}

}  // namespace penumbra::testing
