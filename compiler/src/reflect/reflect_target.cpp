#include "reflect/reflect_target.hpp"

#include <string>

#include "penumbra/compiler/targets.hpp"

namespace penumbra {
namespace {

using Dialect = ReflectionDialect;

// One target's reflection, written in its dialect (target_traits.hpp):
// targets of one dialect reflect alike.
class TargetReflector {
 public:
  TargetReflector(Target target, PassKind pass, const Variant* variant, MapEncoding encoding,
                  std::string_view prefix)
      : target_(target),
        dialect_(traits(target).dialect),
        pass_(pass),
        variant_(variant),
        encoding_(encoding),
        prefix_(prefix) {}

  // The stage's part: its bindings, and the vertex inputs (vertex stage) or
  // the render targets, depth target and extensions (fragment stage).
  Result<PassReflection> reflect(const ShaderInterface& iface) const {
    PassReflection out;
    StageBindings bindings;
    PENUMBRA_TRY_ASSIGN(bindings, stage(iface));
    if (iface.stage == ShaderStage::vertex) {
      out.vert = std::move(bindings);
      for (const StageVariable& input : iface.inputs) out.vertex_inputs.push_back(attribute(input));
      if (dialect_ == Dialect::d3d9) {
        out.vert.uniforms.push_back({std::string(kHalfPixelName), std::string(kHalfPixelParameter),
                                     "float4", std::nullopt, kParamMemberSize,
                                     "c" + std::to_string(half_pixel_register()), 1});
      }
      return out;
    }
    out.frag = std::move(bindings);
    const PassDescription& pass = describe(pass_);
    for (const StageVariable& output : iface.outputs) {
      if (output.name != pass.output.name || output.location != 0) {
        return fail("fragment output '" + output.name + "' at location " +
                    std::to_string(output.location) + " is not the pass's output '" +
                    std::string(pass.output.name) + "' at location 0");
      }
      out.render_targets.push_back(
          {output.name, output.location, std::string(api_format(target_, pass.output.format))});
    }
    if (pass.depth_target) {
      out.depth_target = dialect_ == Dialect::d3d10
                             ? "DXGI_FORMAT_D32_FLOAT"
                             : std::string(api_format(target_, TextureFormat::d32_float));
      out.map_encoding = encoding_;
    }
    // WebGL2 and OpenGL ES 3.0 render to float formats only with this.
    if (dialect_ == Dialect::essl300) out.extensions.push_back("EXT_color_buffer_float");
    return out;
  }

 private:
  Error fail(std::string message) const {
    return make_error(Error::Kind::compile,
                      std::string(to_string(pass_)) + " pass, " + std::string(to_string(target_)),
                      std::move(message));
  }

  Result<StageBindings> stage(const ShaderInterface& iface) const {
    StageBindings out;
    for (const UniformBlock& block : iface.uniform_blocks) {
      if (block.type_name != prefix_ + std::string(kParamsBlock) || block.binding != kParamsSlot) {
        return fail("uniform block '" + block.type_name + "' at binding " +
                    std::to_string(block.binding) + " is not shader_contract.hpp's " + prefix_ +
                    std::string(kParamsBlock) + " at binding " + std::to_string(kParamsSlot));
      }
      params(block, out);
    }
    for (const SampledImage& image : iface.sampled_images) {
      const TextureDescription* texture =
          image.name.starts_with(prefix_)
              ? find_texture(std::string_view(image.name).substr(prefix_.size()))
              : nullptr;
      if (!texture || texture->slot != image.binding || image.set != 0 ||
          image.comparison != texture->sampler.comparison) {
        return fail("sampler '" + image.name + "' at set " + std::to_string(image.set) +
                    ", binding " + std::to_string(image.binding) +
                    " is not a texture of the shader contract at its binding "
                    "(docs/shader-interface.md)");
      }
      out.textures.push_back(texture_binding(*texture, image.arrayed));
      if (texture->constant) {
        if (variant_) out.textures.back().contents = texture_contents(texture->id, *variant_);
        if (!out.textures.back().contents) {
          return fail("sampler '" + image.name + "' is a constant texture with no contents here");
        }
      }
    }
    if (!iface.separate_images.empty() || !iface.separate_samplers.empty()) {
      return fail("separate images and samplers are not part of the shaderlib's source");
    }
    return out;
  }

  // ShadowParams: a block where the target keeps one, else loose uniforms
  // (Direct3D 9's constant registers, GLSL 3.30's struct members), every
  // member as the text declares it: GL reports every member of the struct
  // active once a stage reads one (Mesa does), and D3D9 engines set
  // registers, read or not.
  void params(const UniformBlock& block, StageBindings& out) const {
    const std::string param_block = prefix_ + std::string(kParamsBlock);
    const std::string instance = prefix_ + std::string(kParamsInstance);
    BlockBinding binding{param_block, std::nullopt, std::nullopt, "", block.size, {}};
    for (const BlockMember& member : block.members) {
      ConstantBinding constant{"",
                               member.name,
                               traits(target_).is_hlsl ? "float4" : "vec4",
                               member.offset,
                               member.size,
                               "",
                               0};
      switch (dialect_) {
        case Dialect::spirv:
          constant.name = member.name;
          break;
        case Dialect::glsl450:
        case Dialect::essl300:
          constant.name = param_block + "." + member.name;  // as GL reports block members
          break;
        case Dialect::glsl330:
          constant.name = instance + "." + member.name;
          constant.offset.reset();
          out.uniforms.push_back(constant);
          continue;
        case Dialect::d3d10:
          constant.name = instance + "_" + member.name;
          break;
        case Dialect::d3d9:
          constant.name = instance + "_" + member.name;
          constant.offset.reset();
          constant.reg = "c" + std::to_string(member.offset / kParamMemberSize);
          constant.registers = member.size / kParamMemberSize;
          out.uniforms.push_back(constant);
          continue;
      }
      binding.members.push_back(std::move(constant));
    }
    if (binding.members.empty()) return;
    if (dialect_ == Dialect::spirv) binding.set = block.set;
    if (dialect_ == Dialect::spirv || dialect_ == Dialect::glsl450) binding.binding = block.binding;
    if (dialect_ == Dialect::d3d10) binding.reg = "b" + std::to_string(block.binding);
    out.blocks.push_back(std::move(binding));
  }

  // `arrayed`: a layer of a 2D array texture is read (map_layout array).
  TextureBinding texture_binding(const TextureDescription& texture, bool arrayed) const {
    TextureBinding out;
    out.name = prefix_ + std::string(texture.name);
    const TextureFormat format = dialect_ == Dialect::d3d9 ? texture.dx9_format : texture.format;
    out.format = std::string(api_format(target_, format));
    out.view_format = std::string(api_view_format(target_, format));
    out.mipmapped = texture.mipmapped;
    out.sampler.state = texture.sampler;
    // A reversed-Z map lights a receiver whose reference is at or above the texel.
    out.sampler.state.greater_equal = texture.sampler.comparison && !depth_increases(encoding_);
    const std::string slot = std::to_string(texture.slot);
    switch (dialect_) {
      case Dialect::spirv:
        out.set = 0;
        out.binding = texture.slot;
        break;
      case Dialect::glsl450:
        out.binding = texture.slot;
        break;
      case Dialect::glsl330:
      case Dialect::essl300:
        break;
      case Dialect::d3d10:
        out.type = arrayed ? "Texture2DArray" : "Texture2D";
        out.reg = "t" + slot;
        out.sampler.name = "_" + out.name + "_sampler";
        out.sampler.type = texture.sampler.comparison ? "SamplerComparisonState" : "SamplerState";
        out.sampler.reg = "s" + slot;
        break;
      case Dialect::d3d9:
        out.type = "sampler2D";
        out.reg = "s" + slot;
        break;
    }
    if (out.type.empty()) {
      out.type = std::string(arrayed ? "sampler2DArray" : "sampler2D") +
                 (texture.sampler.comparison ? "Shadow" : "");
    }
    return out;
  }

  VertexAttribute attribute(const StageVariable& input) const {
    static constexpr std::string_view kVulkan[] = {
        "VK_FORMAT_R32_SFLOAT", "VK_FORMAT_R32G32_SFLOAT", "VK_FORMAT_R32G32B32_SFLOAT",
        "VK_FORMAT_R32G32B32A32_SFLOAT"};
    static constexpr std::string_view kDxgi[] = {
        "DXGI_FORMAT_R32_FLOAT", "DXGI_FORMAT_R32G32_FLOAT", "DXGI_FORMAT_R32G32B32_FLOAT",
        "DXGI_FORMAT_R32G32B32A32_FLOAT"};
    static constexpr std::string_view kD3d9[] = {"D3DDECLTYPE_FLOAT1", "D3DDECLTYPE_FLOAT2",
                                                 "D3DDECLTYPE_FLOAT3", "D3DDECLTYPE_FLOAT4"};
    VertexAttribute out;
    out.name = input.name;
    out.components = input.components;
    const std::size_t row = input.components - 1;
    if (traits(target_).is_hlsl) {
      // SPIRV-Cross names location N's input TEXCOORD<N> in every shader model.
      out.semantic = "TEXCOORD" + std::to_string(input.location);
      out.format = std::string(dialect_ == Dialect::d3d9 ? kD3d9[row] : kDxgi[row]);
    } else {
      out.location = input.location;
      out.format = traits(target_).is_text ? "GL_FLOAT" : std::string(kVulkan[row]);
    }
    return out;
  }

  Target target_;
  Dialect dialect_;
  PassKind pass_;
  const Variant* variant_;  // null for passes shared by every variant
  MapEncoding encoding_;    // the map's: the variant's, or the shared pass's
  std::string prefix_;      // heads every name in the text (the function form's)
};

}  // namespace

Result<PassReflection> reflect_target(Target target, PassKind pass, const Variant* variant,
                                      MapEncoding encoding, const ShaderInterface& iface,
                                      std::string_view prefix) {
  return TargetReflector(target, pass, variant, encoding, prefix).reflect(iface);
}

PassReflection join_stages(PassReflection vert, const PassReflection& frag) {
  vert.frag = frag.frag;
  vert.render_targets = frag.render_targets;
  vert.depth_target = frag.depth_target;
  vert.map_encoding = frag.map_encoding;
  vert.extensions = frag.extensions;
  return vert;
}

}  // namespace penumbra
