// The reflection of one pass as one target's emitted text declares it, in
// that API's own terms: what index.json's `reflection.<pass>.<target>` holds
// and what an engine binds by (docs/shader-interface.md, "Reflection").
//
// Which fields a record fills depends on the target's dialect
// (target_traits.hpp); hlsl_dx11 fills what hlsl_dx10 does:
//
// | target    | blocks                 | uniforms              | textures                 |
// |-----------|------------------------|-----------------------|--------------------------|
// | spirv     | set, binding, offsets  | -                     | set, binding             |
// | glsl450   | set, binding, offsets  | -                     | binding                  |
// | glsl330   | -                      | GL names (struct)     | GL names                 |
// | essl300   | GL names, offsets      | -                     | GL names                 |
// | hlsl_dx10 | b#, offsets            | -                     | t#, and s# for samplers  |
// | hlsl_dx9  | -                      | c#, register count    | s#                       |
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/model.hpp"
#include "penumbra/model/shader_contract.hpp"

namespace penumbra {

// One parameter as the target names it: a uniform (GLSL 3.30's struct
// members, Direct3D 9 constants) or a member of a block.
struct ConstantBinding {
  std::string name;       // as the API reports it, e.g. "params.light", "params_light"
  std::string parameter;  // the ShadowParams member it carries, or "half_pixel"
  std::string type;       // "vec4" or "float4"
  std::optional<std::uint32_t> offset;  // bytes, in its block
  std::uint32_t size = kParamMemberSize;
  std::string reg;              // hlsl_dx9: "c0"
  std::uint32_t registers = 0;  // hlsl_dx9: float4 registers it spans
  bool operator==(const ConstantBinding&) const = default;
};

// A uniform block or constant buffer.
struct BlockBinding {
  std::string name;                      // the block as the API names it: "ShadowParams"
  std::optional<std::uint32_t> set;      // spirv, glsl450 (set is spirv only)
  std::optional<std::uint32_t> binding;  // spirv, glsl450
  std::string reg;                       // hlsl_dx10: "b0"
  std::uint32_t size = 0;                // bytes (std140 / cbuffer packing)
  std::vector<ConstantBinding> members;
  bool operator==(const BlockBinding&) const = default;
};

// The sampler a texture must be sampled with, and where the target has a
// sampler object of its own (hlsl_dx10), its name, type and register.
struct SamplerBinding {
  SamplerState state;
  std::string name;  // hlsl_dx10: "_shadow_cmp_sampler"; else empty
  std::string type;  // hlsl_dx10: "SamplerState" or "SamplerComparisonState"
  std::string reg;   // hlsl_dx10: "s2"
  bool operator==(const SamplerBinding&) const = default;
};

struct TextureBinding {
  std::string name;  // the variable, as the API reports it: "shadow_cmp"
  std::string type;  // "sampler2D", "sampler2DShadow", "Texture2D"; arrays: "sampler2DArray", ...
  std::optional<std::uint32_t> set;      // spirv
  std::optional<std::uint32_t> binding;  // spirv, glsl450
  std::string reg;                       // hlsl_dx10: "t2"; hlsl_dx9: "s1"
  std::string format;       // what to create, in the API's terms: "DXGI_FORMAT_R32_TYPELESS"
  std::string view_format;  // hlsl_dx10: the shader resource view's: "DXGI_FORMAT_R32_FLOAT"
  bool mipmapped = false;   // read at explicit mip levels: create and fill every level
  SamplerBinding sampler;
  // A constant texture (hlsl_dx9's disks): the texels to create it with,
  // once, from this record alone.
  std::optional<TextureContents> contents;
  bool operator==(const TextureBinding&) const = default;
};

// What one stage declares.
struct StageBindings {
  std::vector<BlockBinding> blocks;
  std::vector<ConstantBinding> uniforms;
  std::vector<TextureBinding> textures;
  bool operator==(const StageBindings&) const = default;
};

struct VertexAttribute {
  std::string name;                       // the text's input variable: "position"
  std::optional<std::uint32_t> location;  // spirv, GLSL targets
  std::string semantic;                   // HLSL: "TEXCOORD0"
  std::uint32_t components = 0;
  std::string format;  // "VK_FORMAT_R32G32_SFLOAT", "D3DDECLTYPE_FLOAT2", "GL_FLOAT"
  bool operator==(const VertexAttribute&) const = default;
};

struct RenderTarget {
  std::string name;  // the fragment output
  std::uint32_t index = 0;
  std::string format;
  bool operator==(const RenderTarget&) const = default;
};

struct PassReflection {
  std::vector<VertexAttribute> vertex_inputs;
  std::vector<RenderTarget> render_targets;
  std::string depth_target;  // the depth pass: the depth format; else empty
  // The depth pass: the encoding its targets hold (linear: the shader writes
  // the fragment depth; perspective: the rasterizer's, depth test LESS,
  // cleared to 1; perspective_reversed: test GREATER, cleared to 0, the
  // colour target too); else none.
  std::optional<MapEncoding> map_encoding;
  std::vector<std::string> extensions;  // what the API must enable: "EXT_color_buffer_float"
  // The function form: penumbra_visibility()'s declaration in the text,
  // "float penumbra_visibility(vec4 light_clip_position)"; else empty.
  std::string signature;
  StageBindings vert;
  StageBindings frag;
  bool operator==(const PassReflection&) const = default;
};

// `format` in `target`'s API terms: "VK_FORMAT_R32G32_SFLOAT", "GL_RG32F",
// "DXGI_FORMAT_R32G32_FLOAT", "D3DFMT_G32R32F". d32_float is the texture a
// depth map is created as: "DXGI_FORMAT_R32_TYPELESS" for Direct3D 10.
std::string_view api_format(Target target, TextureFormat format);
// The format `target`'s API calls `name` (api_format()'s inverse), or none.
std::optional<TextureFormat> parse_api_format(Target target, std::string_view name);
// "GL_R32F, GL_RG32F, ...": every api_format() of `target`, for messages.
std::string allowed_api_formats(Target target);
// Direct3D 10's shader-resource view of `format` ("DXGI_FORMAT_R32_FLOAT"
// for d32_float); empty for other targets.
std::string_view api_view_format(Target target, TextureFormat format);

std::string_view to_string(TextureFormat format);
std::string_view to_string(Filter filter);
std::string_view to_string(MipFilter filter);

void to_json(nlohmann::json& j, const PassReflection& pass);
// Errors are nlohmann exceptions; load_library turns them into messages that
// name the JSON path.
void from_json(const nlohmann::json& j, PassReflection& pass);

}  // namespace penumbra
