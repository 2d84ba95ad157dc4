#include "penumbra/model/shader_contract.hpp"

#include <algorithm>
#include <cstddef>

#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra {
namespace {

constexpr SamplerState kPoint{false, Filter::nearest, MipFilter::none};

// Indexed by TextureId.
constexpr TextureDescription kTextures[] = {
    {TextureId::shadow_depth, "shadow_depth", 1, TextureFormat::d32_float, TextureFormat::r32_float,
     kPoint, false, "the shadow map, normalized linear depth d = z * depth_scale, point reads"},
    {TextureId::shadow_cmp, "shadow_cmp", 2, TextureFormat::d32_float, TextureFormat::r32_float,
     SamplerState{true, Filter::linear, MipFilter::none}, false,
     "the same shadow map through a LESS_EQUAL comparison sampler (bilinear comparisons)"},
    {TextureId::receivers, "receivers", 3, TextureFormat::rgba32_float, TextureFormat::rgba32_float,
     kPoint, false, "the receivers image: (u, v, z_r, unused) per pixel"},
    {TextureId::shadow_minmax, "shadow_minmax", 4, TextureFormat::rg32_float,
     TextureFormat::rg32_float, SamplerState{false, Filter::nearest, MipFilter::nearest}, true,
     "the min-max mip: (min, max) normalized depth, level l at texel (0, 0) of mip l - 1"},
    {TextureId::minmax_source, "minmax_source", 5, TextureFormat::rg32_float,
     TextureFormat::rg32_float, kPoint, false,
     "the min-max level a minmax_reduce pass reduces: (min, max)"},
    {TextureId::screen_factor, "screen_factor", 6, TextureFormat::rg32_float,
     TextureFormat::rg32_float, kPoint, false,
     "screen_blur: the screen-sized shadow factor of the previous pass, .x"},
    {TextureId::scene_colour, "scene_colour", 7, TextureFormat::rgba32_float,
     TextureFormat::rgba32_float, kPoint, false, "screen_blur: the scene colour, RGBA"},
    {TextureId::pcf_disk, "pcf_disk", 8, TextureFormat::rg32_float, TextureFormat::rg32_float,
     kPoint, false, "the PCF disk: point i (x, y) at texel (i, 0), one row", true},
    {TextureId::blocker_disk, "blocker_disk", 9, TextureFormat::rg32_float,
     TextureFormat::rg32_float, kPoint, false,
     "the blocker-search disk: point i (x, y) at texel (i, 0), one row", true},
    {TextureId::camera_depth, "camera_depth", 10, TextureFormat::d32_float,
     TextureFormat::r32_float, kPoint, false,
     "the deferred pass: the engine's camera depth buffer (any depth format), point reads"},
};

constexpr ParamMember kParams[] = {
    {"shadow_map_size", "W, H, 1/W, 1/H of the shadow map"},
    {"light", "light_world_size L, light_frustum_width Fw, near_plane n, L / Fw"},
    {"sampling", "filter_radius_uv, bias, depth_scale, 1 / depth_scale"},
    {"screen_size", "width, height, 1/width, 1/height of the pass's render target"},
    {"source_size", "min-max build passes: W, H, 1/W, 1/H of the level they read"},
    {"minmax_info", "N, the min-max mip's top level; 0; 0; 0"},
};

constexpr ParamMember kDeferredParams[] = {
    {"camera_inverse_0", "column 0 of the inverse of the camera's view-projection"},
    {"camera_inverse_1", "column 1 of it"},
    {"camera_inverse_2", "column 2 of it"},
    {"camera_inverse_3", "column 3 of it"},
    {"light_view_proj_0", "column 0 of the light's view-projection, which drew the map"},
    {"light_view_proj_1", "column 1 of it"},
    {"light_view_proj_2", "column 2 of it"},
    {"light_view_proj_3", "column 3 of it"},
    {"camera_depth_range",
     "a, b with clip z / w = a depth + b; the depth the buffer is cleared to; 0"},
};

constexpr TextureId kMinmaxInitReads[] = {TextureId::shadow_depth};
constexpr TextureId kMinmaxReduceReads[] = {TextureId::minmax_source};
constexpr TextureId kQueryReads[] = {TextureId::receivers,  TextureId::shadow_depth,
                                     TextureId::shadow_cmp, TextureId::shadow_minmax,
                                     TextureId::pcf_disk,   TextureId::blocker_disk};
constexpr TextureId kBlurReads[] = {TextureId::screen_factor, TextureId::receivers};
constexpr TextureId kCompositeReads[] = {TextureId::screen_factor, TextureId::scene_colour};
constexpr TextureId kDeferredReads[] = {TextureId::camera_depth, TextureId::shadow_depth,
                                        TextureId::shadow_cmp,   TextureId::shadow_minmax,
                                        TextureId::pcf_disk,     TextureId::blocker_disk};

constexpr VertexInput kLightSpacePosition{"position", 3, "light-view space position"};
constexpr VertexInput kClipPosition{
    "position", 2,
    "clip-space position of one triangle covering the target: (-1,-1), (3,-1), (-1,3)"};

// Indexed by PassKind.
constexpr PassDescription kPasses[] = {
    {PassKind::depth,
     "passes/depth.vert",
     "passes/depth.frag",
     "depth",
     false,
     kLightSpacePosition,
     {"depth_out", TextureFormat::r32_float},
     true,
     {}},
    {PassKind::minmax_init,
     "passes/fullscreen.vert",
     "passes/minmax_init.frag",
     "minmax_init",
     false,
     kClipPosition,
     {"minmax", TextureFormat::rg32_float},
     false,
     kMinmaxInitReads},
    {PassKind::minmax_reduce,
     "passes/fullscreen.vert",
     "passes/minmax_reduce.frag",
     "minmax_reduce",
     false,
     kClipPosition,
     {"minmax", TextureFormat::rg32_float},
     false,
     kMinmaxReduceReads},
    {PassKind::query,
     "passes/fullscreen.vert",
     "passes/query.frag",
     "fullscreen",
     true,
     kClipPosition,
     {"visibility", TextureFormat::rg32_float},
     false,
     kQueryReads},
    {PassKind::blur_h,
     "passes/fullscreen.vert",
     "passes/blur_h.frag",
     "blur_h",
     true,
     kClipPosition,
     {"blurred", TextureFormat::rg32_float},
     false,
     kBlurReads},
    {PassKind::blur_v,
     "passes/fullscreen.vert",
     "passes/blur_v.frag",
     "blur_v",
     true,
     kClipPosition,
     {"blurred", TextureFormat::rg32_float},
     false,
     kBlurReads},
    {PassKind::composite,
     "passes/fullscreen.vert",
     "passes/composite.frag",
     "composite",
     false,
     kClipPosition,
     {"colour", TextureFormat::rgba32_float},
     false,
     kCompositeReads},
    {PassKind::deferred,
     "passes/fullscreen.vert",
     "passes/deferred.frag",
     "deferred",
     true,
     kClipPosition,
     {"visibility", TextureFormat::rg32_float},
     false,
     kDeferredReads},
};

// The query's techniques that read the map alone, and those that read the
// min-max mip its build passes make of it; the deferred pass is the query's
// alternative for an engine's own camera, run instead of it.
constexpr PassKind kSinglePass[] = {PassKind::depth, PassKind::query, PassKind::deferred};
constexpr PassKind kMinmaxPasses[] = {PassKind::depth, PassKind::minmax_init,
                                      PassKind::minmax_reduce, PassKind::query, PassKind::deferred};
constexpr PassKind kScreenBlurPasses[] = {PassKind::depth, PassKind::query, PassKind::blur_h,
                                          PassKind::blur_v, PassKind::composite};

// The keys of the techniques that read the map alone end with the map's
// encoding and layout.
constexpr std::string_view kMapKeys[] = {"map_encoding", "map_layout"};
constexpr std::string_view kGridKeys[] = {"kernel", "map_encoding", "map_layout"};
constexpr std::string_view kPoissonKeys[] = {"pcf_samples",    "disk",         "rotation",
                                             "receiver_plane", "map_encoding", "map_layout"};
constexpr std::string_view kMinmaxPoissonKeys[] = {"pcf_samples", "disk", "rotation",
                                                   "map_encoding"};
constexpr std::string_view kPcssKeys[] = {"blocker_samples", "pcf_samples",    "disk",
                                          "rotation",        "receiver_plane", "map_encoding",
                                          "map_layout"};
constexpr std::string_view kMinmaxPcfKeys[] = {"kernel", "traversal", "map_encoding"};
constexpr std::string_view kBackprojectionKeys[] = {"traversal", "max_nodes", "map_encoding"};
constexpr std::string_view kScreenBlurKeys[] = {"blur_radius", "depth_aware"};
constexpr std::string_view kBitmaskKeys[] = {"traversal", "max_nodes", "light_bits",
                                             "map_encoding"};
constexpr std::string_view kTraversalEncoding[] = {"traversal", "map_encoding"};
constexpr std::string_view kDepthAware[] = {"depth_aware"};
constexpr std::string_view kRotationEncoding[] = {"rotation", "map_encoding"};
constexpr std::string_view kRotationPlaneMap[] = {"rotation", "receiver_plane", "map_encoding",
                                                  "map_layout"};

// Indexed by Technique.
constexpr TechniqueDescription kTechniques[] = {
    {Technique::hard, "hard", kMapKeys, kMapKeys, kSinglePass, false},
    {Technique::pcf_grid, "pcf_grid", kGridKeys, kMapKeys, kSinglePass, false},
    {Technique::pcf_poisson, "pcf_poisson", kPoissonKeys, kRotationPlaneMap, kSinglePass, false},
    {Technique::pcss, "pcss", kPcssKeys, kRotationPlaneMap, kSinglePass, false},
    {Technique::minmax_pcf, "minmax_pcf", kMinmaxPcfKeys, kTraversalEncoding, kMinmaxPasses, true},
    {Technique::backprojection, "backprojection", kBackprojectionKeys, kBackprojectionKeys,
     kMinmaxPasses, true},
    {Technique::pcss_minmax, "pcss_minmax", kMinmaxPoissonKeys, kRotationEncoding, kMinmaxPasses,
     true},
    {Technique::screen_blur, "screen_blur", kScreenBlurKeys, kDepthAware, kScreenBlurPasses, false},
    {Technique::bitmask_backprojection, "bitmask_backprojection", kBitmaskKeys, kBackprojectionKeys,
     kMinmaxPasses, true, true},
};

// The tables are indexed by their enums: each row's enum must be its index.
constexpr bool rows_in_enum_order() {
  for (std::size_t i = 0; i < std::size(kTextures); ++i) {
    if (static_cast<std::size_t>(kTextures[i].id) != i) return false;
  }
  for (std::size_t i = 0; i < std::size(kPasses); ++i) {
    if (static_cast<std::size_t>(kPasses[i].kind) != i) return false;
  }
  for (std::size_t i = 0; i < std::size(kTechniques); ++i) {
    if (static_cast<std::size_t>(kTechniques[i].technique) != i) return false;
  }
  return true;
}
static_assert(rows_in_enum_order());
static_assert(std::size(kPasses) == kAllPassKinds.size());
static_assert(std::size(kTechniques) == kAllTechniques.size());

}  // namespace

std::uint32_t texel_components(TextureFormat format) {
  switch (format) {
    case TextureFormat::rg32_float:
      return 2;
    case TextureFormat::rgba32_float:
      return 4;
    case TextureFormat::r32_float:
    case TextureFormat::d32_float:
      return 1;
  }
  return 1;
}

const TextureDescription& describe(TextureId texture) {
  return kTextures[static_cast<std::size_t>(texture)];
}

std::string_view contents_disk(TextureId texture) {
  if (texture == TextureId::pcf_disk) return "pcf";
  if (texture == TextureId::blocker_disk) return "blocker";
  return {};
}

std::optional<TextureContents> texture_contents(TextureId texture, const Variant& variant) {
  const std::optional<Disk>* disk = texture == TextureId::pcf_disk       ? &variant.pcf_disk
                                    : texture == TextureId::blocker_disk ? &variant.blocker_disk
                                                                         : nullptr;
  if (!disk || !*disk) return std::nullopt;
  TextureContents contents{static_cast<std::uint32_t>((*disk)->points.size()), 1, {}};
  for (const Point2& point : (*disk)->points) {
    contents.texels.push_back(point[0]);
    contents.texels.push_back(point[1]);
  }
  return contents;
}

std::span<const TextureDescription> all_textures() {
  return kTextures;
}

const TextureDescription* find_texture(std::string_view name) {
  for (const TextureDescription& texture : kTextures) {
    if (texture.name == name) return &texture;
  }
  return nullptr;
}

const TextureDescription* find_bound_texture(std::string_view name) {
  if (const TextureDescription* texture = find_texture(name)) return texture;
  return name.starts_with(kFunctionPrefix) ? find_texture(name.substr(kFunctionPrefix.size()))
                                           : nullptr;
}

std::span<const ParamMember> param_members() {
  return kParams;
}

std::span<const ParamMember> deferred_param_members() {
  return kDeferredParams;
}

std::uint32_t half_pixel_register() {
  return static_cast<std::uint32_t>(std::size(kParams));
}

const PassDescription& describe(PassKind pass) {
  return kPasses[static_cast<std::size_t>(pass)];
}

const TechniqueDescription& describe(Technique technique) {
  return kTechniques[static_cast<std::size_t>(technique)];
}

bool can_emit(Technique technique, Target target) {
  return !describe(technique).integer_ops || traits(target).integer_ops;
}

bool can_emit(const Variant& variant, Target target) {
  return can_emit(variant.technique, target) && inexact_walk(variant, target).empty() &&
         layout_unsupported(map_layout(variant.keys), target).empty();
}

bool runs_pass(PassKind pass, const Variant& variant) {
  const std::span<const PassKind> passes = describe(variant.technique).passes;
  if (std::ranges::find(passes, pass) == passes.end()) return false;
  return std::ranges::any_of(kAllForms, [&](Form form) {
    return builds_form(variant, form) && form_reads_pass(form, pass);
  });
}

bool form_reads_pass(Form form, PassKind pass) {
  switch (pass) {
    case PassKind::depth:
    case PassKind::minmax_init:
    case PassKind::minmax_reduce:
      return true;
    case PassKind::query:
    case PassKind::blur_h:
    case PassKind::blur_v:
    case PassKind::composite:
      return form == Form::query;
    case PassKind::deferred:
      return form == Form::deferred;
  }
  return false;
}

bool has_function_form(Technique technique) {
  const std::span<const PassKind> passes = describe(technique).passes;
  return std::ranges::find(passes, PassKind::deferred) != passes.end();
}

bool has_form(Technique technique, Form form) {
  return form == Form::query || has_function_form(technique);
}

std::vector<Form> technique_forms(Technique technique) {
  std::vector<Form> out;
  for (Form form : kAllForms) {
    if (has_form(technique, form)) out.push_back(form);
  }
  return out;
}

bool builds_form(const Variant& variant, Form form) {
  return has_form(variant.technique, form) &&
         std::ranges::find(variant.forms, form) != variant.forms.end();
}

std::vector<Form> built_forms(const Variant& variant) {
  std::vector<Form> out;
  for (Form form : kAllForms) {
    if (builds_form(variant, form)) out.push_back(form);
  }
  return out;
}

std::string form_not_built(const Variant& variant, Form form) {
  if (builds_form(variant, form)) return {};
  if (!has_form(variant.technique, form)) {
    return "technique " + std::string(to_string(variant.technique)) + " has no " +
           std::string(to_string(form)) + " form";
  }
  return built_without(form, built_forms(variant));
}

std::string built_without(Form form, std::span<const Form> built) {
  return "built without the " + std::string(to_string(form)) +
         " form (its forms: " + to_string(built) + ")";
}

}  // namespace penumbra
