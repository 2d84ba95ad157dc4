#include "engine_shaders.hpp"

#include <charconv>

#include "penumbra/model/target_traits.hpp"

namespace penumbra {
namespace {

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// A float literal that reads back as the nearest float to `value`.
std::string literal(double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), float(value));
  std::string text(buffer, end);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

// "vec4(a, b, c, d)" or "float4(a, b, c, d)".
std::string row_literal(const std::array<double, 4>& row, bool hlsl) {
  std::string out = hlsl ? "float4(" : "vec4(";
  for (std::size_t k = 0; k < 4; ++k) out += (k ? ", " : "") + literal(row[k]);
  return out + ")";
}

// "vecN(dot(R0, p), ...)": the rows as constants dotted with `p`.
std::string transformed(const std::string& prefix, bool hlsl) {
  std::string out = hlsl ? "float4(" : "vec4(";
  for (int r = 0; r < 4; ++r)
    out += (r ? ", " : "") + ("dot(" + prefix + std::to_string(r) + ", p)");
  return out + ")";
}

std::string constants(const Matrix4& m, const std::string& prefix, bool hlsl) {
  std::string out;
  for (int r = 0; r < 4; ++r) {
    out += (hlsl ? "static const float4 " : "const vec4 ") + prefix + std::to_string(r) + " = " +
           row_literal(m[std::size_t(r)], hlsl) + ";\n";
  }
  return out;
}

// `depth`'s linear_z() of the clip position `clip`, in shader text: the
// function form's own expression, so both round alike.
std::string clip_linear_z(const LightClipDepth& depth, const std::string& clip) {
  if (!depth.orthographic) return clip + ".w";
  std::string d = "(" + clip + ".z / " + clip + ".w)";
  if (!depth.zero_to_one) d = "(0.5 * " + d + " + 0.5)";
  return "((1.0 - " + d + ") * " + literal(depth.near_plane) + " + " + d + " * " +
         literal(depth.far_plane) + ")";
}

std::string glsl_version(Target target) {
  if (target == Target::glsl450) return "#version 450\n";
  if (target == Target::glsl330) return "#version 330\n";
  return "#version 300 es\nprecision highp float;\n";
}

// ", vec4(...), vec4(...), vec4(...)" (an array's last argument its layer,
// an int): `call`'s arguments, or nothing.
std::string call_arguments(const std::optional<CallLight>& call, bool hlsl) {
  if (!call) return {};
  const auto vector = [&](const std::array<float, 4>& v) {
    return ", " + row_literal({v[0], v[1], v[2], v[3]}, hlsl);
  };
  return vector(call->light) + vector(call->sampling) +
         (call->map_layer ? ", " + std::to_string(*call->map_layer) : vector(call->map_tile));
}

}  // namespace

Matrix4 camera_clip(const reference::Stage& stage, int width, int height, Target target) {
  const reference::CameraFrame frame = reference::camera_frame(stage.camera, width, height);
  // Camera space: (right, up, forward) from the eye; the picture's x / w is
  // the ray's sx / half_width, its upward y / w is sy / half_height.
  const bool d3d = traits(target).is_hlsl;
  const double y_sign = d3d ? 1.0 : -1.0;
  const double near = 0.5, far = 100.0;
  const double a = d3d ? far / (far - near) : (far + near) / (far - near);
  const double b = d3d ? -far * near / (far - near) : -2.0 * far * near / (far - near);
  // Row r of the matrix: scale * (axis . (p - eye)) + offset.
  const auto row = [&](const std::array<double, 3>& axis, double scale, double offset) {
    return std::array<double, 4>{scale * axis[0], scale * axis[1], scale * axis[2],
                                 offset - scale * dot(axis, stage.camera.eye)};
  };
  return {row(frame.right, 1.0 / frame.half_width, 0.0),
          row(frame.up, y_sign / frame.half_height, 0.0), row(frame.forward, a, b),
          row(frame.forward, 1.0, 0.0)};
}

LightClipDepth light_clip_depth(const LightParams& light, double far_plane, Target target) {
  return {light.orthographic(), traits(target).is_hlsl || target == Target::spirv, light.near_plane,
          far_plane};
}

Matrix4 light_clip(const LightParams& light, const LightClipDepth& depth, Target target) {
  const double y_sign = traits(target).is_hlsl ? -1.0 : 1.0;
  const double n = light.near_plane;
  if (depth.orthographic) {
    const double scale = 2.0 / light.frustum_width;
    // z / w = d, or 2 d - 1, for d = (z - n) / (f - n).
    const double z_scale = (depth.zero_to_one ? 1.0 : 2.0) / (depth.far_plane - n);
    const double z_offset = -n * z_scale - (depth.zero_to_one ? 0.0 : 1.0);
    return {{{scale, 0.0, 0.0, 0.0},
             {0.0, y_sign * scale, 0.0, 0.0},
             {0.0, 0.0, z_scale, z_offset},
             {0.0, 0.0, 0.0, 1.0}}};
  }
  const double scale = 2.0 * n / light.frustum_width;
  return {{{scale, 0.0, 0.0, 0.0},
           {0.0, y_sign * scale, 0.0, 0.0},
           {0.0, 0.0, 0.0, 0.0},
           {0.0, 0.0, 1.0, 0.0}}};
}

bool takes_pixel(const PassReflection& reflection) {
  return reflection.signature.find("pixel") != std::string::npos;
}

std::string engine_vertex_shader(Target target, const Matrix4& camera, const Matrix4& light,
                                 const VertexOptions& options) {
  const bool hlsl = traits(target).is_hlsl;
  const bool sm3 = hlsl && traits(target).shader_model == 3 && options.pass_pixel;
  std::string out = hlsl ? "" : glsl_version(target);
  out += "// The engine's camera and the light's view-projection, as constants.\n";
  out += constants(camera, "CAMERA", hlsl) + constants(light, "LIGHT", hlsl);
  if (sm3) {
    // Pixel (x, y) from the picture's top left, times w: (0.5 x / w + 0.5)
    // width and (0.5 - 0.5 y / w) height, Direct3D's y being up.
    Matrix4 pixel{};
    for (int c = 0; c < 4; ++c) {
      pixel[0][c] = 0.5 * options.width * (camera[0][c] + camera[3][c]);
      pixel[1][c] = 0.5 * options.height * (camera[3][c] - camera[1][c]);
      pixel[3][c] = camera[3][c];
    }
    out += constants(pixel, "PIXEL", hlsl);
  }
  if (hlsl) {
    out += "struct Varyings {\n  float4 light_clip_position : TEXCOORD0;\n";
    if (sm3) out += "  float4 pixel_position : TEXCOORD1;\n";
    // Direct3D 9's POSITION, which glslang's HLSL front end takes only as
    // SV_Position (as the library's own dx9 shim does).
    out += "  float4 position : SV_Position;\n};\n";
    out += "Varyings main(float3 position : TEXCOORD0) {\n";
    out += "  float4 p = float4(position, 1.0);\n  Varyings out_;\n";
    out += "  out_.position = " + transformed("CAMERA", true) + ";\n";
    if (options.half_pixel_offset) {
      out += "  out_.position.xy += float2(" + literal(-1.0 / options.width) + ", " +
             literal(1.0 / options.height) + ") * out_.position.w;\n";
    }
    out += "  out_.light_clip_position = " + transformed("LIGHT", true) + ";\n";
    if (sm3) out += "  out_.pixel_position = " + transformed("PIXEL", true) + ";\n";
    return out + "  return out_;\n}\n";
  }
  // Locations need GLSL 4.10 on inputs of a fragment stage; 3.30 and ES
  // 3.00 match the varying by name.
  const bool locations = target == Target::glsl450;
  out += "layout(location = 0) in vec3 position;\n";
  out +=
      std::string(locations ? "layout(location = 0) out" : "out") + " vec4 light_clip_position;\n";
  out += "void main() {\n  vec4 p = vec4(position, 1.0);\n";
  out += "  gl_Position = " + transformed("CAMERA", false) + ";\n";
  out += "  light_clip_position = " + transformed("LIGHT", false) + ";\n}\n";
  return out;
}

std::string engine_fragment_shader(Target target, const PassReflection& reflection,
                                   const std::string& function_text, const LightClipDepth& depth,
                                   const std::optional<CallLight>& call) {
  const bool hlsl = traits(target).is_hlsl;
  const bool pixel = takes_pixel(reflection);
  const std::string arguments = call_arguments(call, hlsl);
  const std::string result = "light_clip_position.x, light_clip_position.y, visible, " +
                             clip_linear_z(depth, "light_clip_position");
  if (hlsl) {
    const bool sm3 = traits(target).shader_model == 3;
    std::string out = function_text + "\n";
    out += "float4 main(float4 light_clip_position : TEXCOORD0";
    // SV_Position is the pixel's centre; Direct3D 9's pixel position comes
    // from the vertex stage, interpolated (engine_vertex_shader()).
    if (pixel) out += sm3 ? ", float4 position : TEXCOORD1" : ", float4 position : SV_Position";
    out += sm3 ? ") : COLOR0 {\n" : ") : SV_Target {\n";
    out += "  float visible = penumbra_visibility(light_clip_position";
    out += !pixel ? "" : sm3 ? ", floor(position.xy / position.w)" : ", floor(position.xy)";
    out += arguments + ");\n";
    return out + "  return float4(" + result + ");\n}\n";
  }
  std::string out = glsl_version(target);
  for (const std::string& extension : reflection.extensions) {
    out += "#extension " + extension + " : require\n";
  }
  out += function_text + "\n";
  out += target == Target::glsl450 ? "layout(location = 0) in" : "in";
  out += " vec4 light_clip_position;\nlayout(location = 0) out vec4 colour;\n";
  out += "void main() {\n  float visible = penumbra_visibility(light_clip_position";
  out += std::string(pixel ? ", floor(gl_FragCoord.xy)" : "") + arguments + ");\n";
  return out + "  colour = vec4(" + result + ");\n}\n";
}

}  // namespace penumbra
