// engine_consumer_gl_lights atlas|array [OUT.png]: engine_consumer_gl's box
// lit by two spot lights whose maps the OpenGL engine keeps in one texture:
// as its two tiles (atlas), as Godot's and Unity's keep their spot lights',
// or as its two layers (array), as Filament's and Babylon.js's keep theirs.
// One loop in the ground's shader calls that layout's function form once per
// light, each call naming that light's matrix, ShadowParams `light` and
// `sampling` and its tile or layer (docs/techniques.md, "Map layouts").
// Light 0 is engine_consumer's light, in the atlas's right tile or the
// array's layer 1; light 1 the same light mirrored in x with half its size,
// in the left tile or layer 0. The picture is light 0's visibility, which
// must be engine_consumer's (by default shadow_gl_LAYOUT.png); it prints
// each light's penumbra.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "engine_shadows/shaders.hpp"
#include "gl_engine.hpp"

namespace {

using namespace scene;
using namespace gl_engine;

constexpr int kLights = 2;

int fail(const std::string& message) {
  std::fprintf(stderr, "engine_consumer_gl_lights: %s\n", message.c_str());
  return 1;
}

// A light as the engine keeps it in its uniform arrays.
struct Light {
  Mat4 matrix{};
  std::vector<float> light;     // ShadowParams' `light` for it
  std::vector<float> sampling;  // and `sampling`
  std::vector<float> tile;      // atlas: its tile, u, v, width, height
  int place = 0;                // its tile's column of maps in the atlas, or its layer
};

Light make_light(float size, bool mirrored, int place) {
  Light out;
  out.matrix = light_matrix();
  if (mirrored) out.matrix[0] = -out.matrix[0];  // x negated before the projection
  const float m = kMapSize;
  out.light = {size, kFrustumWidth, kNear, size / kFrustumWidth};
  out.sampling = {2 / m, 0.0f, 1 / kFar, kFar};  // the ground is no caster: no bias
  out.tile = {0.5f * float(place), 0.0f, 0.5f, 1.0f};
  out.place = place;
  return out;
}

// The block's values: the texture's size (an atlas's; an array's layers');
// the members each call names instead are left zero, the rest unread.
nlohmann::json block_values(bool array) {
  const float w = array ? kMapSize : kLights * kMapSize, h = kMapSize;
  const std::vector<float> zero(4, 0.0f);
  return {{"shadow_map_size", {w, h, 1 / w, 1 / h}},
          {"light", zero},
          {"sampling", zero},
          {"screen_size", zero},
          {"source_size", zero},
          {"minmax_info", zero},
          {"map_tile", zero},
          {"map_layer", zero}};
}

const char* kPositionStage =
    "#version 330 core\n"
    "in vec3 position;\n"
    "uniform mat4 camera;\n"
    "uniform mat4 lights[2];\n"
    "out vec4 light_clip_position[2];\n"
    "void main() {\n"
    "  for (int i = 0; i < 2; ++i) light_clip_position[i] = lights[i] * vec4(position, 1.0);\n"
    "  gl_Position = camera * vec4(position, 1.0);\n"
    "}\n";

// Every light's map, drawn into the bound depth target: the box from that
// light, through its tile's viewport or into its layer.
bool draw_maps(const std::vector<Light>& lights, GLuint map, bool array, std::string& log) {
  const GLuint depth_program = link(kPositionStage, "#version 330 core\nvoid main() {}\n", log);
  if (depth_program == 0) return false;
  glUseProgram(depth_program);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  const std::vector<Vec3> box = box_triangles();
  glBindVertexArray(vertex_array(box));
  for (const Light& light : lights) {
    glUniformMatrix4fv(glGetUniformLocation(depth_program, "camera"), 1, GL_FALSE,
                       light.matrix.data());
    if (array) {
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, map, 0, light.place);
      glViewport(0, 0, kMapSize, kMapSize);
      glClear(GL_DEPTH_BUFFER_BIT);
    } else {
      glViewport(light.place * kMapSize, 0, kMapSize, kMapSize);
    }
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(box.size()));
  }
  return true;
}

// The ground's program: every light's visibility in one loop, light i's
// in channel i; `light_places` are the tiles (vec4) or the layers (int).
GLuint shading_program(const std::string& function, bool array, std::string& log) {
  const std::string stage = "#version 330 core\n" + function +
                            "\nin vec4 light_clip_position[2];\n"
                            "uniform vec4 light_params[2];\n"
                            "uniform vec4 light_sampling[2];\n"
                            "uniform " +
                            (array ? "int" : "vec4") +
                            " light_places[2];\n"
                            "out vec4 colour;\n"
                            "void main() {\n"
                            "  colour = vec4(0.0, 0.0, 0.0, 1.0);\n"
                            "  for (int i = 0; i < 2; ++i) {\n"
                            "    colour[i] = penumbra_visibility(light_clip_position[i],\n"
                            "        light_params[i], light_sampling[i], light_places[i]);\n"
                            "  }\n"
                            "}\n";
  return link(kPositionStage, stage, log);
}

// The location of element `i` of the uniform array `name`.
GLint element(GLuint program, std::string name, int i) {
  name.append("[").append(std::to_string(i)).append("]");
  return glGetUniformLocation(program, name.c_str());
}

void set_lights(GLuint program, const std::vector<Light>& lights, bool array) {
  for (int i = 0; i < kLights; ++i) {
    const Light& light = lights[std::size_t(i)];
    glUniformMatrix4fv(element(program, "lights", i), 1, GL_FALSE, light.matrix.data());
    glUniform4fv(element(program, "light_params", i), 1, light.light.data());
    glUniform4fv(element(program, "light_sampling", i), 1, light.sampling.data());
    if (array) {
      glUniform1i(element(program, "light_places", i), light.place);
    } else {
      glUniform4fv(element(program, "light_places", i), 1, light.tile.data());
    }
  }
}

std::ptrdiff_t penumbra_pixels(const std::vector<png_byte>& grey) {
  return std::ranges::count_if(grey, [](png_byte v) { return v > 0 && v < 255; });
}

}  // namespace

int main(int argc, char** argv) {
  const std::string layout = argc > 1 ? argv[1] : "";
  if (layout != "atlas" && layout != "array") {
    return fail("usage: engine_consumer_gl_lights atlas|array [OUT.png]");
  }
  const bool array = layout == "array";
  const std::string out = argc > 2 ? argv[2] : "shadow_gl_" + layout + ".png";
  nlohmann::json reflection;
  std::string log;
  const penumbra::shaders::Function* function =
      pcss_function({.map_encoding = "perspective", .map_layout = layout}, reflection, log);
  if (function == nullptr) return fail(log);
  if (!create_context()) return fail("no EGL display can make an OpenGL 3.3 core context current");

  const std::vector<Light> lights = {make_light(kLightSize, false, 1),
                                     make_light(0.5f * kLightSize, true, 0)};
  const GLuint map = array ? depth_target(kMapSize, kMapSize, kLights)
                           : depth_target(kLights * kMapSize, kMapSize);
  if (!draw_maps(lights, map, array, log)) return fail("the depth program: " + log);

  picture_target();
  const GLuint ground_program = shading_program(std::string(function->text), array, log);
  if (ground_program == 0) return fail("the ground's program: " + log);
  glUseProgram(ground_program);
  set_lights(ground_program, lights, array);
  if (!bind_function_inputs(ground_program, reflection, map, block_values(array), log)) {
    return fail(log);
  }
  draw_ground(ground_program);

  const std::vector<png_byte> first = read_channel(0, log);
  const std::vector<png_byte> second = read_channel(1, log);
  if (first.empty() || second.empty()) return fail(log);
  if (penumbra_pixels(second) == 0) return fail("light 1 casts no soft shadow");
  if (!write_png(out, first)) return fail("cannot write " + out);
  std::printf(
      "engine_consumer_gl_lights: %s on %s: wrote %s (%dx%d; pixels in the penumbra: light 0 "
      "%td, light 1 %td)\n",
      std::string(function->variant).c_str(),
      reinterpret_cast<const char*>(glGetString(GL_RENDERER)), out.c_str(), kImageSize, kImageSize,
      penumbra_pixels(first), penumbra_pixels(second));
  return 0;
}
