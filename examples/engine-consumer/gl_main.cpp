// engine_consumer_gl [OUT.png]: the box and light of engine_consumer, drawn
// as an OpenGL engine draws shadows of its own. It renders its own shadow
// map (hardware depth through a perspective light projection) and
// forward-shades the ground with its own shaders, whose fragment stage calls
// the variant's function form, penumbra_visibility(), compiled into this
// program (engine_shadows). Everything it binds to that function, it takes
// from the function form's reflection. The ground's visibility is written
// as a greyscale PNG (white: lit, black: the umbra), by default
// shadow_gl.png.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <png.h>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine_shadows/shaders.hpp"
#include "scene.hpp"

namespace {

using namespace scene;
using Mat4 = std::array<float, 16>;  // column-major, as glUniformMatrix4fv takes it

int fail(const std::string& message) {
  std::fprintf(stderr, "engine_consumer_gl: %s\n", message.c_str());
  return 1;
}

// The light's view-projection: x and y scaled by 2n / Fw, w = z, and z
// mapped to [-w, w] from n to f, so that the depth buffer stores
// f (z - n) / (z (f - n)): the `perspective` map encoding.
Mat4 light_matrix() {
  const float s = 2.0f * kNear / kFrustumWidth;
  const float a = (kFar + kNear) / (kFar - kNear);
  const float b = -2.0f * kFar * kNear / (kFar - kNear);
  return {s, 0, 0, 0, 0, s, 0, 0, 0, 0, a, 1, 0, 0, b, 0};
}

// The engine's camera: the ground seen from straight above, x and y in
// [-2, 2] filling the picture (depth unused).
Mat4 camera_matrix() {
  const float s = 1.0f / kGroundHalfWidth;
  return {s, 0, 0, 0, 0, s, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
}

std::vector<Vec3> ground_triangles() {
  const float h = kGroundHalfWidth, z = kGroundZ;
  return {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, -h, z}, {h, h, z}, {-h, h, z}};
}

// An OpenGL 3.3 core context with nothing to draw on but its own
// framebuffers: Mesa's surfaceless platform, else the default display.
bool create_context() {
  EGLDisplay display =
      eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
    display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) return false;
  }
  const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                      EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &configs) || configs == 0) {
    return false;
  }
  const EGLint pbuffer_attributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
  const EGLSurface surface = eglCreatePbufferSurface(display, config, pbuffer_attributes);
  eglBindAPI(EGL_OPENGL_API);
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  return context != EGL_NO_CONTEXT && eglMakeCurrent(display, surface, surface, context);
}

GLuint compile(GLenum stage, const std::string& source, std::string& log) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::vector<char> buffer(4096);
    glGetShaderInfoLog(shader, GLsizei(buffer.size()), nullptr, buffer.data());
    log += buffer.data();
  }
  return shader;
}

// A linked program of `vertex` and `fragment`, or 0 with `log` saying why.
GLuint link(const std::string& vertex, const std::string& fragment, std::string& log) {
  const GLuint program = glCreateProgram();
  glAttachShader(program, compile(GL_VERTEX_SHADER, vertex, log));
  glAttachShader(program, compile(GL_FRAGMENT_SHADER, fragment, log));
  glBindAttribLocation(program, 0, "position");
  glLinkProgram(program);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::vector<char> buffer(4096);
    glGetProgramInfoLog(program, GLsizei(buffer.size()), nullptr, buffer.data());
    log += buffer.data();
    return 0;
  }
  return program;
}

// A vertex array of `triangles` at attribute 0.
GLuint vertex_array(const std::vector<Vec3>& triangles) {
  GLuint array = 0, buffer = 0;
  glGenVertexArrays(1, &array);
  glBindVertexArray(array);
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(triangles.size() * sizeof(Vec3)), triangles.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  return array;
}

// A sampler object in a reflected sampler state (docs/shader-interface.md).
GLuint sampler_object(const nlohmann::json& state) {
  GLuint sampler = 0;
  glGenSamplers(1, &sampler);
  const GLint filter = state.at("filter") == "linear" ? GL_LINEAR : GL_NEAREST;
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, filter);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, filter);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  const std::string comparison = state.at("comparison");
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE,
                      comparison == "none" ? GL_NONE : GL_COMPARE_REF_TO_TEXTURE);
  if (comparison != "none") {
    glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_FUNC,
                        comparison == "less_equal" ? GL_LEQUAL : GL_GEQUAL);
  }
  return sampler;
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

// Binds the function form's textures and constants in `program` as its
// reflection names them: the map on consecutive units from 0, each through
// a sampler object in its reflected state; ShadowParams as loose uniforms
// (glsl330 has them), or as a block at binding 0.
bool bind_function_inputs(GLuint program, const nlohmann::json& reflection, GLuint map,
                          std::string& log) {
  const nlohmann::json& frag = reflection.at("frag");
  GLuint unit = 0;
  for (const nlohmann::json& texture : frag.value("textures", nlohmann::json::array())) {
    const std::string name = texture.at("name");
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, map);
    glBindSampler(unit, sampler_object(texture.at("sampler")));
    glUniform1i(glGetUniformLocation(program, name.c_str()), GLint(unit));
    ++unit;
  }
  const nlohmann::json values = shadow_params();
  const auto value = [&](const nlohmann::json& member) {
    return values.at(member.at("parameter").get<std::string>()).get<std::vector<float>>();
  };
  for (const nlohmann::json& uniform : frag.value("uniforms", nlohmann::json::array())) {
    const std::string name = uniform.at("name");
    const GLint location = glGetUniformLocation(program, name.c_str());
    if (location < 0) {
      log = "the program has no uniform " + name;
      return false;
    }
    glUniform4fv(location, 1, value(uniform).data());
  }
  for (const nlohmann::json& block : frag.value("blocks", nlohmann::json::array())) {
    std::vector<float> data(block.at("size").get<std::size_t>() / sizeof(float));
    for (const nlohmann::json& member : block.at("members")) {
      const std::vector<float> v = value(member);
      std::copy(v.begin(), v.end(),
                data.begin() + std::ptrdiff_t(member.at("offset").get<std::size_t>() / 4));
    }
    GLuint buffer = 0;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_UNIFORM_BUFFER, buffer);
    glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(),
                 GL_STATIC_DRAW);
    const std::string name = block.at("name");
    const GLuint index = glGetUniformBlockIndex(program, name.c_str());
    if (index == GL_INVALID_INDEX) {
      log = "the program has no uniform block " + name;
      return false;
    }
    glUniformBlockBinding(program, index, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, buffer);
  }
  return true;
}

bool write_png(const std::string& path, const std::vector<png_byte>& grey) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = kImageSize;
  image.height = kImageSize;
  image.format = PNG_FORMAT_GRAY;
  return png_image_write_to_file(&image, path.c_str(), 0, grey.data(), 0, nullptr) != 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "shadow_gl.png";

  // The function form of PCSS (16 and 16 samples on the whitepaper's disk)
  // for a map stored as hardware depth of a perspective projection.
  const penumbra::VariantKeys keys{.blocker_samples = 16,
                                   .pcf_samples = 16,
                                   .disk = "whitepaper16",
                                   .map_encoding = "perspective"};
  const penumbra::shaders::Function* function =
      engine_shadows::find_function(penumbra::Technique::pcss, keys, penumbra::Target::glsl330);
  if (function == nullptr) return fail("shadows.json does not build this pcss variant for glsl330");
  const nlohmann::json reflection = nlohmann::json::parse(function->reflection);
  if (!reflection.value("extensions", nlohmann::json::array()).empty()) {
    return fail("the function form needs GLSL extensions, which this engine does not enable");
  }

  if (!create_context()) return fail("no EGL display can make an OpenGL 3.3 core context current");

  // The engine's own shadow map: the box's depth from the light.
  GLuint map = 0;
  glGenTextures(1, &map);
  glBindTexture(GL_TEXTURE_2D, map);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, kMapSize, kMapSize, 0, GL_DEPTH_COMPONENT,
               GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  GLuint map_framebuffer = 0;
  glGenFramebuffers(1, &map_framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, map_framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map, 0);
  glDrawBuffer(GL_NONE);

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
  std::string log;
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
  GLuint colour = 0, picture = 0;
  glGenTextures(1, &colour);
  glBindTexture(GL_TEXTURE_2D, colour);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kImageSize, kImageSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  glGenFramebuffers(1, &picture);
  glBindFramebuffer(GL_FRAMEBUFFER, picture);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
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
  const Mat4 camera = camera_matrix();
  glUniformMatrix4fv(glGetUniformLocation(ground_program, "camera"), 1, GL_FALSE, camera.data());
  glUniformMatrix4fv(glGetUniformLocation(ground_program, "light"), 1, GL_FALSE, light.data());
  if (!bind_function_inputs(ground_program, reflection, map, log)) return fail(log);

  glViewport(0, 0, kImageSize, kImageSize);
  glDisable(GL_DEPTH_TEST);
  const std::vector<Vec3> ground = ground_triangles();
  glBindVertexArray(vertex_array(ground));
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(ground.size()));

  // Row 0 of the read-back is y = -2, as engine_consumer's picture's row 0.
  std::vector<png_byte> rgba(std::size_t(kImageSize) * kImageSize * 4);
  glReadPixels(0, 0, kImageSize, kImageSize, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    return fail("OpenGL error " + std::to_string(error));
  }
  std::vector<png_byte> grey(std::size_t(kImageSize) * kImageSize);
  for (std::size_t k = 0; k < grey.size(); ++k) grey[k] = rgba[4 * k];
  if (!write_png(out, grey)) return fail("cannot write " + out);
  const auto penumbra_pixels =
      std::ranges::count_if(grey, [](png_byte v) { return v > 0 && v < 255; });
  std::printf("engine_consumer_gl: %s on %s: wrote %s (%dx%d, %td pixels in the penumbra)\n",
              std::string(function->variant).c_str(),
              reinterpret_cast<const char*>(glGetString(GL_RENDERER)), out.c_str(), kImageSize,
              kImageSize, penumbra_pixels);
  return 0;
}
