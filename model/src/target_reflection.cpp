#include "penumbra/model/target_reflection.hpp"

#include <cstddef>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "penumbra/model/json_number.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra {
namespace {

enum class Api { vulkan, gl, d3d10, d3d9 };

Api api_of(Target target) {
  switch (traits(target).dialect) {
    case ReflectionDialect::spirv:
      return Api::vulkan;
    case ReflectionDialect::glsl450:
    case ReflectionDialect::glsl330:
    case ReflectionDialect::essl300:
      return Api::gl;
    case ReflectionDialect::d3d10:
      return Api::d3d10;
    case ReflectionDialect::d3d9:
      return Api::d3d9;
  }
  return Api::vulkan;
}

// Rows indexed by TextureFormat, columns by Api.
constexpr std::string_view kFormats[][4] = {
    {"VK_FORMAT_R32_SFLOAT", "GL_R32F", "DXGI_FORMAT_R32_FLOAT", "D3DFMT_R32F"},
    {"VK_FORMAT_R32G32_SFLOAT", "GL_RG32F", "DXGI_FORMAT_R32G32_FLOAT", "D3DFMT_G32R32F"},
    {"VK_FORMAT_R32G32B32A32_SFLOAT", "GL_RGBA32F", "DXGI_FORMAT_R32G32B32A32_FLOAT",
     "D3DFMT_A32B32G32R32F"},
    // Direct3D 9 has no sampled depth format of its own; its depth pass
    // tests against any depth buffer while the map is the R32F colour target.
    {"VK_FORMAT_D32_SFLOAT", "GL_DEPTH_COMPONENT32F", "DXGI_FORMAT_R32_TYPELESS", "D3DFMT_D24X8"},
};

constexpr std::string_view kFormatNames[] = {"r32_float", "rg32_float", "rgba32_float",
                                             "d32_float"};

// Omits empty strings, unset optionals and empty arrays: each target's
// record holds only the fields that target has.
template <typename T>
void put(nlohmann::json& j, const char* key, const std::optional<T>& value) {
  if (value) j[key] = *value;
}
void put(nlohmann::json& j, const char* key, const std::string& value) {
  if (!value.empty()) j[key] = value;
}
template <typename T>
void put(nlohmann::json& j, const char* key, const std::vector<T>& values) {
  if (!values.empty()) j[key] = values;
}

template <typename T>
void get(const nlohmann::json& j, const char* key, std::optional<T>& value) {
  if (!j.contains(key)) return;
  if constexpr (std::is_arithmetic_v<T>)
    value = number_as<T>(j.at(key));
  else
    value = j.at(key).get<T>();
}
void get(const nlohmann::json& j, const char* key, std::string& value) {
  if (j.contains(key)) j.at(key).get_to(value);
}
template <typename T>
void get(const nlohmann::json& j, const char* key, std::vector<T>& values) {
  if (j.contains(key)) j.at(key).get_to(values);
}

template <typename Enum, std::size_t N>
Enum parse_enum(const nlohmann::json& j, const std::string_view (&names)[N], const char* what) {
  const std::string text = j.get<std::string>();
  for (std::size_t i = 0; i < N; ++i) {
    if (names[i] == text) return static_cast<Enum>(i);
  }
  throw nlohmann::json::other_error::create(501, std::string("unknown ") + what + " '" + text + "'",
                                            &j);
}

constexpr std::string_view kFilterNames[] = {"nearest", "linear"};
constexpr std::string_view kMipFilterNames[] = {"none", "nearest"};

}  // namespace

std::string_view api_format(Target target, TextureFormat format) {
  return kFormats[static_cast<std::size_t>(format)][static_cast<std::size_t>(api_of(target))];
}

std::optional<TextureFormat> parse_api_format(Target target, std::string_view name) {
  for (std::size_t i = 0; i < std::size(kFormats); ++i) {
    const auto format = static_cast<TextureFormat>(i);
    if (api_format(target, format) == name) return format;
  }
  return std::nullopt;
}

std::string allowed_api_formats(Target target) {
  std::string out;
  for (std::size_t i = 0; i < std::size(kFormats); ++i) {
    out +=
        (out.empty() ? "" : ", ") + std::string(api_format(target, static_cast<TextureFormat>(i)));
  }
  return out;
}

std::string_view api_view_format(Target target, TextureFormat format) {
  if (api_of(target) != Api::d3d10) return "";
  return format == TextureFormat::d32_float ? "DXGI_FORMAT_R32_FLOAT" : api_format(target, format);
}

std::string_view to_string(TextureFormat format) {
  return kFormatNames[static_cast<std::size_t>(format)];
}
std::string_view to_string(Filter filter) {
  return kFilterNames[static_cast<std::size_t>(filter)];
}
std::string_view to_string(MipFilter filter) {
  return kMipFilterNames[static_cast<std::size_t>(filter)];
}

void to_json(nlohmann::json& j, const SamplerState& s) {
  j = {{"comparison", !s.comparison     ? "none"
                      : s.greater_equal ? "greater_equal"
                                        : "less_equal"},
       {"filter", to_string(s.filter)},
       {"mip_filter", to_string(s.mip_filter)},
       {"address", "clamp_to_edge"}};
}
void from_json(const nlohmann::json& j, SamplerState& s) {
  const std::string comparison = j.at("comparison").get<std::string>();
  if (comparison != "none" && comparison != "less_equal" && comparison != "greater_equal") {
    throw nlohmann::json::other_error::create(501, "unknown comparison '" + comparison + "'", &j);
  }
  s.comparison = comparison != "none";
  s.greater_equal = comparison == "greater_equal";
  s.filter = parse_enum<Filter>(j.at("filter"), kFilterNames, "filter");
  s.mip_filter = parse_enum<MipFilter>(j.at("mip_filter"), kMipFilterNames, "mip_filter");
  if (j.at("address").get<std::string>() != "clamp_to_edge") {
    throw nlohmann::json::other_error::create(501, "address must be clamp_to_edge", &j);
  }
}

void to_json(nlohmann::json& j, const ConstantBinding& c) {
  j = {{"name", c.name}, {"parameter", c.parameter}, {"type", c.type}, {"size", c.size}};
  put(j, "offset", c.offset);
  put(j, "register", c.reg);
  if (c.registers > 0) j["registers"] = c.registers;
}
void from_json(const nlohmann::json& j, ConstantBinding& c) {
  j.at("name").get_to(c.name);
  j.at("parameter").get_to(c.parameter);
  j.at("type").get_to(c.type);
  number_at(j, "size", c.size);
  get(j, "offset", c.offset);
  get(j, "register", c.reg);
  if (j.contains("registers")) number_at(j, "registers", c.registers);
}

void to_json(nlohmann::json& j, const BlockBinding& b) {
  j = {{"name", b.name}, {"size", b.size}, {"members", b.members}};
  put(j, "set", b.set);
  put(j, "binding", b.binding);
  put(j, "register", b.reg);
}
void from_json(const nlohmann::json& j, BlockBinding& b) {
  j.at("name").get_to(b.name);
  number_at(j, "size", b.size);
  j.at("members").get_to(b.members);
  get(j, "set", b.set);
  get(j, "binding", b.binding);
  get(j, "register", b.reg);
}

void to_json(nlohmann::json& j, const SamplerBinding& s) {
  j = s.state;
  put(j, "name", s.name);
  put(j, "type", s.type);
  put(j, "register", s.reg);
}
void from_json(const nlohmann::json& j, SamplerBinding& s) {
  j.get_to(s.state);
  get(j, "name", s.name);
  get(j, "type", s.type);
  get(j, "register", s.reg);
}

void to_json(nlohmann::json& j, const TextureContents& c) {
  j = {{"width", c.width}, {"height", c.height}, {"texels", c.texels}};
}
void from_json(const nlohmann::json& j, TextureContents& c) {
  number_at(j, "width", c.width);
  number_at(j, "height", c.height);
  const nlohmann::json& values = j.at("texels");
  if (!values.is_array()) {
    throw nlohmann::json::type_error::create(302, "texels must be an array of numbers", &values);
  }
  c.texels.clear();
  for (const nlohmann::json& value : values) c.texels.push_back(number_as<float>(value));
  const std::size_t texels = std::size_t{c.width} * c.height;
  if (texels == 0 || c.texels.size() % texels != 0 || c.texels.size() / texels > 4) {
    throw nlohmann::json::other_error::create(
        501, "texels must hold 1 to 4 floats for each of the width x height texels", &j);
  }
}

void to_json(nlohmann::json& j, const TextureBinding& t) {
  j = {{"name", t.name}, {"type", t.type}, {"format", t.format}, {"sampler", t.sampler}};
  put(j, "set", t.set);
  put(j, "binding", t.binding);
  put(j, "register", t.reg);
  put(j, "view_format", t.view_format);
  if (t.mipmapped) j["mipmapped"] = true;
  if (t.contents) j["contents"] = *t.contents;
}
void from_json(const nlohmann::json& j, TextureBinding& t) {
  j.at("name").get_to(t.name);
  j.at("type").get_to(t.type);
  j.at("format").get_to(t.format);
  j.at("sampler").get_to(t.sampler);
  get(j, "set", t.set);
  get(j, "binding", t.binding);
  get(j, "register", t.reg);
  get(j, "view_format", t.view_format);
  t.mipmapped = j.value("mipmapped", false);
  if (j.contains("contents")) t.contents = j.at("contents").get<TextureContents>();
}

void to_json(nlohmann::json& j, const StageBindings& s) {
  j = nlohmann::json::object();
  put(j, "blocks", s.blocks);
  put(j, "uniforms", s.uniforms);
  put(j, "textures", s.textures);
}
void from_json(const nlohmann::json& j, StageBindings& s) {
  get(j, "blocks", s.blocks);
  get(j, "uniforms", s.uniforms);
  get(j, "textures", s.textures);
}

void to_json(nlohmann::json& j, const VertexAttribute& a) {
  j = {{"name", a.name}, {"components", a.components}, {"format", a.format}};
  put(j, "location", a.location);
  put(j, "semantic", a.semantic);
}
void from_json(const nlohmann::json& j, VertexAttribute& a) {
  j.at("name").get_to(a.name);
  number_at(j, "components", a.components);
  j.at("format").get_to(a.format);
  get(j, "location", a.location);
  get(j, "semantic", a.semantic);
}

void to_json(nlohmann::json& j, const RenderTarget& r) {
  j = {{"name", r.name}, {"index", r.index}, {"format", r.format}};
}
void from_json(const nlohmann::json& j, RenderTarget& r) {
  j.at("name").get_to(r.name);
  number_at(j, "index", r.index);
  j.at("format").get_to(r.format);
}

void to_json(nlohmann::json& j, const PassReflection& p) {
  j = {{"vertex_inputs", p.vertex_inputs},
       {"render_targets", p.render_targets},
       {"vert", p.vert},
       {"frag", p.frag}};
  put(j, "depth_target", p.depth_target);
  if (p.map_encoding) j["map_encoding"] = to_string(*p.map_encoding);
  put(j, "extensions", p.extensions);
  put(j, "signature", p.signature);
}
void from_json(const nlohmann::json& j, PassReflection& p) {
  j.at("vertex_inputs").get_to(p.vertex_inputs);
  j.at("render_targets").get_to(p.render_targets);
  j.at("vert").get_to(p.vert);
  j.at("frag").get_to(p.frag);
  get(j, "depth_target", p.depth_target);
  std::string encoding;
  get(j, "map_encoding", encoding);
  if (!encoding.empty()) {
    p.map_encoding = parse_map_encoding(encoding);
    if (!p.map_encoding) {
      throw nlohmann::json::other_error::create(
          501, "unknown map_encoding '" + encoding + "'; allowed " + allowed_map_encodings(), &j);
    }
  }
  get(j, "extensions", p.extensions);
  get(j, "signature", p.signature);
}

}  // namespace penumbra
