#include "pass_binding.hpp"

#include <cstdio>

namespace penumbra::d3d {
namespace {

// Floats as text that reads back to the same float.
std::string number(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  return text;
}

std::string vec4(const std::array<float, 4>& v) {
  return number(v[0]) + " " + number(v[1]) + " " + number(v[2]) + " " + number(v[3]);
}

Error unbindable(const std::string& where, const std::string& what) {
  return make_error(Error::Kind::bad_input, where, what);
}

// The value a constant carries: its ShadowParams member, or D3D9's half
// pixel, (1 / width, 1 / height, 0, 0) of what the draw covers
// (docs/engines/d3d9.md).
Result<std::array<float, 4>> value_of(const ConstantBinding& constant, const ParamBlock& params,
                                      const DrawTarget& target, const std::string& where) {
  if (constant.parameter == kHalfPixelParameter) {
    return std::array<float, 4>{1.0f / static_cast<float>(target.width),
                                1.0f / static_cast<float>(target.height), 0.0f, 0.0f};
  }
  const auto found = params.find(constant.parameter);
  if (found == params.end()) {
    return unbindable(where, "ShadowParams member '" + constant.parameter + "' (constant '" +
                                 constant.name + "') has no value in the params");
  }
  return found->second;
}

Status write_constants(std::string& block, const StageBindings& stage, const char* name,
                       const ParamBlock& params, const DrawTarget& target,
                       const std::string& where) {
  for (const ConstantBinding& uniform : stage.uniforms) {
    if (uniform.reg.empty() || uniform.reg[0] != 'c') {
      return unbindable(where, "constant '" + uniform.name + "' has no c# register (Direct3D 9)");
    }
    auto value = value_of(uniform, params, target, where);
    if (!value) return value.error();
    block += "constant " + std::string(name) + " " + uniform.reg + " " + vec4(*value) + "\n";
  }
  for (const BlockBinding& cbuffer : stage.blocks) {
    if (cbuffer.reg.empty() || cbuffer.reg[0] != 'b') {
      return unbindable(where, "block '" + cbuffer.name + "' has no b# register (Direct3D 10/11)");
    }
    for (const ConstantBinding& member : cbuffer.members) {
      auto value = value_of(member, params, target, where);
      if (!value) return value.error();
      if (!member.offset || *member.offset + 16 > cbuffer.size) {
        return unbindable(where,
                          "member '" + member.name + "' lies outside block '" + cbuffer.name + "'");
      }
      block += "member " + std::string(name) + " " + cbuffer.reg + " " +
               std::to_string(cbuffer.size) + " " + std::to_string(*member.offset) + " " +
               vec4(*value) + "\n";
    }
  }
  return {};
}

std::string sampler_line(const std::string& reg, const SamplerState& state) {
  const char* comparison = !state.comparison     ? "plain"
                           : state.greater_equal ? "compare_greater"
                                                 : "compare";
  return "sampler " + reg + " " + std::string(to_string(state.filter)) + " " +
         std::string(to_string(state.mip_filter)) + " clamp_to_edge " + comparison + "\n";
}

Status write_textures(Job& job, std::string& block, const StageBindings& frag,
                      const PassTextures& textures, const std::string& where) {
  const bool d3d9 = job.runtime() == D3dRuntime::d3d9;
  for (const TextureBinding& texture : frag.textures) {
    int id = 0;
    std::string view_format = texture.view_format;
    if (texture.contents) {
      id = job.constant_texture(texture.format, *texture.contents);
    } else {
      const TextureDescription* described = find_bound_texture(texture.name);
      const auto given = described ? textures.find(described->id) : textures.end();
      if (given == textures.end()) {
        return unbindable(
            where, "it reads texture '" + texture.name + "', which this run does not provide");
      }
      id = given->second.id;
      if (!given->second.view_format.empty()) view_format = given->second.view_format;
    }
    block += "texture " + texture.reg + " " + std::to_string(id) + (d3d9 ? "" : " " + view_format) +
             "\n";
    // Direct3D 9 keeps a texture's sampler state at its own s#.
    block += sampler_line(d3d9 ? texture.reg : texture.sampler.reg, texture.sampler.state);
  }
  return {};
}

}  // namespace

Status draw_pass(Job& job, const D3dPass& pass, const std::string& where,
                 const PassTextures& textures, const ParamBlock& params, const DrawTarget& target,
                 const DrawGeometry& geometry) {
  auto vs = job.shader(pass.vert, "vs");
  if (!vs) return vs.error();
  auto ps = job.shader(pass.frag, "ps");
  if (!ps) return ps.error();
  const PassReflection& reflection = pass.reflection;
  std::string block = "draw\n";
  if (target.colour) {
    block += "colour " + std::to_string(*target.colour) + " " + std::to_string(target.level) + "\n";
  }
  if (target.depth) block += "depth " + std::to_string(*target.depth) + "\n";
  if (target.clear_colour) block += "clear_colour " + vec4(*target.clear_colour) + "\n";
  if (target.clear_depth) block += "clear_depth " + number(*target.clear_depth) + "\n";
  if (target.depth_greater) block += "depth_greater\n";
  block += "vs " + std::to_string(*vs) + "\nps " + std::to_string(*ps) + "\n";
  unsigned offset = 0;
  for (const VertexAttribute& input : reflection.vertex_inputs) {
    block += "input " + input.semantic + " " + input.format + " " + std::to_string(offset) + "\n";
    offset += input.components * static_cast<unsigned>(sizeof(float));
  }
  block += "vertices " + std::to_string(geometry.buffer) + " " + std::to_string(offset) + " " +
           std::to_string(geometry.count) + "\n";
  PENUMBRA_TRY(write_constants(block, reflection.vert, "vs", params, target, where));
  PENUMBRA_TRY(write_constants(block, reflection.frag, "ps", params, target, where));
  PENUMBRA_TRY(write_textures(job, block, reflection.frag, textures, where));
  job.append(block + "end\n");
  return {};
}

}  // namespace penumbra::d3d
