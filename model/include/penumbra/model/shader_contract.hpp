// The shader interface, described once: the parameter block, the textures a
// pass may read and how an engine must create and sample each, the passes
// (their sources, vertex inputs and render targets) and the passes each
// technique runs. The compiler writes every target's reflection from this
// description (target_reflection.hpp) and the shaderlib takes its bindings
// from it (variant.glsl); engines read the reflection, never this table.
// docs/shader-interface.md is its prose.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/model/pass.hpp"

namespace penumbra {

// Texel formats, named by their layout; each API's own name comes from
// api_format() (target_reflection.hpp).
enum class TextureFormat {
  r32_float,     // one 32-bit float
  rg32_float,    // two 32-bit floats
  rgba32_float,  // four 32-bit floats
  d32_float,     // a 32-bit float depth format, sampled (and compared) as depth
};

// Floats per texel: 1, 2 or 4.
std::uint32_t texel_components(TextureFormat format);

enum class Filter { nearest, linear };

// How a texture's mip levels are chosen: `none` for textures read at LOD 0
// only (minification filter without mipmaps), `nearest` for the min-max mip,
// read at explicit levels.
enum class MipFilter { none, nearest };

// The sampler state a texture needs. Every texture here is addressed
// clamp-to-edge (docs/shader-interface.md), so no border colour
// is ever read.
struct SamplerState {
  bool comparison = false;          // compare with LESS_EQUAL: lit when reference <= texel
  Filter filter = Filter::nearest;  // minification and magnification
  MipFilter mip_filter = MipFilter::none;
  bool greater_equal = false;  // with comparison: GREATER_EQUAL instead (reversed-Z maps)
  bool operator==(const SamplerState&) const = default;
};

// The textures a pass may read, in binding order.
enum class TextureId {
  shadow_depth,   // the map, point reads
  shadow_cmp,     // the same map through a comparison sampler
  receivers,      // receiver (u, v, z_r) per pixel
  shadow_minmax,  // the min-max mip (Dmitriev 2007)
  minmax_source,  // the level a minmax_reduce pass reduces
  screen_factor,  // screen_blur's factor buffer
  scene_colour,   // screen_blur's scene colour
  pcf_disk,       // the PCF disk's points, where the target reads them from a texture
  blocker_disk,   // the blocker-search disk's points, likewise
  camera_depth,   // the deferred pass: the engine's camera depth buffer, point reads
};

struct TextureDescription {
  TextureId id;
  std::string_view name;  // the variable's name in every target's text
  // Vulkan binding in set 0, GLSL 4.50 binding, and the number of the
  // Direct3D t# and s# registers.
  std::uint32_t slot;
  // What the engine creates. The map is a depth texture on targets with a
  // comparison sampler and an R32F colour texture for Direct3D 9.
  TextureFormat format;
  TextureFormat dx9_format;
  SamplerState sampler;
  bool mipmapped;            // read at explicit mip levels (shadow_minmax)
  std::string_view content;  // one line for docs and messages
  // Filled by the library, not by the engine's frame: the variant's data
  // (texture_contents()), listed with the reflection.
  bool constant = false;
};

const TextureDescription& describe(TextureId texture);

// A constant texture's texels, as the library lists them: `width` x
// `height` texels of the texture's format, row 0 first, every component.
struct TextureContents {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> texels;
  bool operator==(const TextureContents&) const = default;
};

// The contents of constant texture `texture` for `variant` (a disk: point i
// at texel (i, 0)); none when the variant has no such data.
std::optional<TextureContents> texture_contents(TextureId texture, const Variant& variant);
// The disk constant texture `texture` holds, as index.json's variant "disks"
// names it ("pcf", "blocker"); empty for any other texture.
std::string_view contents_disk(TextureId texture);
std::span<const TextureDescription> all_textures();
// The texture named `name` in the text, or none.
const TextureDescription* find_texture(std::string_view name);

// The prefix of every name a function form declares at file scope
// (docs/function-form.md): its textures are "penumbra_shadow_depth", ...
inline constexpr std::string_view kFunctionPrefix = "penumbra_";
// The texture a pass's text names `name`, or a function form's text names
// kFunctionPrefix + `name`; or none.
const TextureDescription* find_bound_texture(std::string_view name);

// The parameter block, ShadowParams: every member a vec4, so that Direct3D
// 9 constant registers map one to one (member i is register c<i>).
inline constexpr std::string_view kParamsBlock = "ShadowParams";
inline constexpr std::string_view kParamsInstance = "params";
inline constexpr std::uint32_t kParamsSlot = 0;  // set 0 binding, Direct3D b0

struct ParamMember {
  std::string_view name;     // e.g. "shadow_map_size"
  std::string_view content;  // "W, H, 1/W, 1/H"
};
std::span<const ParamMember> param_members();
// What the deferred pass's ShadowParams declares after param_members(): the
// camera's and the light's matrices, column by column, and how to read the
// camera's depth (docs/deferred-mask.md). The block's other passes end
// before them, so their layout is the same in every pass.
std::span<const ParamMember> deferred_param_members();
inline constexpr std::uint32_t kParamMemberSize = 16;  // bytes: one vec4

// Direct3D 9 vertex shaders: SPIRV-Cross's half-pixel constant, which the
// engine sets to (1 / width, 1 / height) of the render target (the offset
// that aligns D3D9's pixel centres with the other APIs'). It takes the
// register after ShadowParams in every vertex shader.
inline constexpr std::string_view kHalfPixelName = "gl_HalfPixel";
inline constexpr std::string_view kHalfPixelParameter = "half_pixel";
std::uint32_t half_pixel_register();

// A vertex attribute: position, in location 0.
struct VertexInput {
  std::string_view name;
  std::uint32_t components;  // float components
  std::string_view content;
};

// A fragment output, written to colour target 0.
struct PassOutput {
  std::string_view name;
  TextureFormat format;
};

struct PassDescription {
  PassKind kind;
  std::string_view vertex_source;    // in shaderlib/
  std::string_view fragment_source;  // in shaderlib/
  std::string_view vertex_file;      // output file stem of the vertex stage, e.g. "fullscreen"
  bool per_variant;  // the fragment stage depends on the variant (else one per target)
  VertexInput input;
  PassOutput output;
  bool depth_target;  // also writes depth (the depth pass fills a depth map)
  // Every texture the pass may read; which appear in a target's text
  // depends on the technique and the target (no shadow_cmp for hlsl_dx9).
  std::span<const TextureId> reads;
};

const PassDescription& describe(PassKind pass);

// A technique: its name, the keys that select its variants, the passes it
// runs, in order (`deferred`, where listed, runs in the query's place, not
// after it), whether it reads the min-max mip and whether its shader needs
// integer bit operations. Its CPU reference is reference/'s evaluate().
struct TechniqueDescription {
  Technique technique;
  std::string_view name;                            // in manifests and index.json
  std::span<const std::string_view> keys;           // from kVariantKeyNames, in that order
  std::span<const std::string_view> optional_keys;  // keys with a default a manifest may omit
  std::span<const PassKind> passes;
  bool reads_minmax;
  // Keeps its state in integer bits, so only targets with integer_ops
  // (target_traits.hpp) can emit it; manifests asking others are refused.
  bool integer_ops = false;
};

const TechniqueDescription& describe(Technique technique);

// Whether `technique`'s shaders can be emitted for `target`: all but an
// integer_ops technique on a target without integers (hlsl_dx9).
bool can_emit(Technique technique, Target target);
// Whether `variant` can be built for `target`: its technique can be emitted
// there, keeps its promise there (minmax_pcf's exact count: inexact_walk())
// and its map layout is read there (layout_unsupported()). A manifest asking
// otherwise is refused.
bool can_emit(const Variant& variant, Target target);

// True when `variant` is built with `pass`: its technique runs it and one of
// the forms it is built in reads it (form_reads_pass()).
bool runs_pass(PassKind pass, const Variant& variant);
// Whether `form` reads `pass`: every form reads the depth pass and the
// min-max chain; the query form its query, blur and composite passes; the
// deferred form its deferred pass; the function form no pass of its own.
bool form_reads_pass(Form form, PassKind pass);

// Whether `technique` has a function form (docs/function-form.md) and a
// deferred pass (docs/deferred-mask.md): every technique but screen_blur,
// whose blur passes follow the query.
bool has_function_form(Technique technique);
// Whether `technique` has `form`: every technique the query form, and those
// with has_function_form() the deferred and function forms.
bool has_form(Technique technique, Form form);
// The forms `technique` has, in kAllForms order.
std::vector<Form> technique_forms(Technique technique);
// Whether `variant` is built in `form`: it asks for it and its technique has it.
bool builds_form(const Variant& variant, Form form);
// The forms `variant` is built in, in kAllForms order.
std::vector<Form> built_forms(const Variant& variant);
// Why `variant` has no `form`, for messages ("built without the query form
// (its forms: function)", "technique screen_blur has no function form"), or
// empty when it is built in it.
std::string form_not_built(const Variant& variant, Form form);
// "built without the query form (its forms: function)": the reason for a
// variant built in `built` only, for messages that know no Variant.
std::string built_without(Form form, std::span<const Form> built);

}  // namespace penumbra
