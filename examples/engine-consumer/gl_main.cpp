// engine_consumer_gl [OUT.png]: the box and light of engine_consumer, drawn
// as an OpenGL engine draws shadows of its own. It renders its own shadow
// map (hardware depth through a perspective light projection) and
// forward-shades the ground with its own shaders, whose fragment stage calls
// the variant's function form, penumbra_visibility(), compiled into this
// program (engine_shadows). Everything it binds to that function, it takes
// from the function form's reflection. The ground's visibility is written
// as a greyscale PNG (white: lit, black: the umbra), by default
// shadow_gl.png.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "engine_shadows/shaders.hpp"
#include "gl_engine.hpp"

namespace {

using namespace scene;
using namespace gl_engine;

int fail(const std::string& message) {
  std::fprintf(stderr, "engine_consumer_gl: %s\n", message.c_str());
  return 1;
}

// The values of ShadowParams (docs/shader-interface.md) by member name.
nlohmann::json shadow_params() {
  const float m = kMapSize, s = kImageSize;
  return {{"shadow_map_size", {m, m, 1 / m, 1 / m}},
          {"light", {kLightSize, kFrustumWidth, kNear, kLightSize / kFrustumWidth}},
          {"sampling", {2 / m, 0.0f, 1 / kFar, kFar}},  // the ground is no caster: no bias
          {"screen_size", {s, s, 1 / s, 1 / s}},
          {"source_size", {0, 0, 0, 0}},
          {"minmax_info", {0, 0, 0, 0}}};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "shadow_gl.png";

  // PCSS's function form for a map stored as hardware depth of a
  // perspective projection.
  nlohmann::json reflection;
  std::string log;
  const penumbra::shaders::Function* function =
      pcss_function({.map_encoding = "perspective"}, reflection, log);
  if (function == nullptr) return fail(log);

  if (!create_context()) return fail("no EGL display can make an OpenGL 3.3 core context current");

  // The engine's own shadow map: the box's depth from the light.
  const GLuint map = depth_target(kMapSize, kMapSize);

  const Mat4 light = light_matrix();
  const std::string position_stage =
      "#version 330 core\n"
      "in vec3 position;\n"
      "uniform mat4 camera;\n"
      "uniform mat4 light;\n"
      "out vec4 light_clip_position;\n"
      "void main() {\n"
      "  light_clip_position = light * vec4(position, 1.0);\n"
      "  gl_Position = camera * vec4(position, 1.0);\n"
      "}\n";
  const GLuint depth_program = link(position_stage, "#version 330 core\nvoid main() {}\n", log);
  if (depth_program == 0) return fail("the depth program: " + log);
  glUseProgram(depth_program);
  glUniformMatrix4fv(glGetUniformLocation(depth_program, "camera"), 1, GL_FALSE, light.data());
  glViewport(0, 0, kMapSize, kMapSize);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  const std::vector<Vec3> box = box_triangles();
  glBindVertexArray(vertex_array(box));
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(box.size()));

  // The forward pass: the ground, shaded by its visibility.
  // Its target first: creating a texture binds it to the active unit, and
  // the function's textures take units from 0.
  picture_target();
  const std::string shading_stage =
      "#version 330 core\n" + std::string(function->text) +
      "\nin vec4 light_clip_position;\n"
      "out vec4 colour;\n"
      "void main() {\n"
      "  float visibility = penumbra_visibility(light_clip_position);\n"
      "  colour = vec4(visibility, visibility, visibility, 1.0);\n"
      "}\n";
  const GLuint ground_program = link(position_stage, shading_stage, log);
  if (ground_program == 0) return fail("the ground's program: " + log);
  glUseProgram(ground_program);
  glUniformMatrix4fv(glGetUniformLocation(ground_program, "light"), 1, GL_FALSE, light.data());
  if (!bind_function_inputs(ground_program, reflection, map, shadow_params(), log)) {
    return fail(log);
  }

  draw_ground(ground_program);

  // Row 0 of the read-back is y = -2, as engine_consumer's picture's row 0.
  const std::vector<png_byte> grey = read_channel(0, log);
  if (grey.empty()) return fail(log);
  if (!write_png(out, grey)) return fail("cannot write " + out);
  const auto penumbra_pixels =
      std::ranges::count_if(grey, [](png_byte v) { return v > 0 && v < 255; });
  std::printf("engine_consumer_gl: %s on %s: wrote %s (%dx%d, %td pixels in the penumbra)\n",
              std::string(function->variant).c_str(),
              reinterpret_cast<const char*>(glGetString(GL_RENDERER)), out.c_str(), kImageSize,
              kImageSize, penumbra_pixels);
  return 0;
}
