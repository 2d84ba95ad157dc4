#include "gl_engine.hpp"

#include <algorithm>
#include <vector>

namespace gl_engine {

using namespace scene;

namespace {

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

}  // namespace

const penumbra::shaders::Function* pcss_function(const penumbra::VariantKeys& keys,
                                                 nlohmann::json& reflection, std::string& log) {
  penumbra::VariantKeys pcss = keys;
  pcss.blocker_samples = 16;
  pcss.pcf_samples = 16;
  pcss.disk = "whitepaper16";
  const penumbra::shaders::Function* function =
      engine_shadows::find_function(penumbra::Technique::pcss, pcss, penumbra::Target::glsl330);
  if (function == nullptr) {
    log = "shadows.json does not build this pcss variant for glsl330";
    return nullptr;
  }
  reflection = nlohmann::json::parse(function->reflection);
  if (!reflection.value("extensions", nlohmann::json::array()).empty()) {
    log = "the function form needs GLSL extensions, which this engine does not enable";
    return nullptr;
  }
  return function;
}

Mat4 light_matrix() {
  const float s = 2.0f * kNear / kFrustumWidth;
  const float a = (kFar + kNear) / (kFar - kNear);
  const float b = -2.0f * kFar * kNear / (kFar - kNear);
  return {s, 0, 0, 0, 0, s, 0, 0, 0, 0, a, 1, 0, 0, b, 0};
}

void draw_ground(GLuint program) {
  // The engine's camera: the ground seen from straight above, x and y in
  // [-2, 2] filling the picture (depth unused).
  const float s = 1.0f / kGroundHalfWidth;
  const Mat4 camera = {s, 0, 0, 0, 0, s, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
  glUniformMatrix4fv(glGetUniformLocation(program, "camera"), 1, GL_FALSE, camera.data());
  glViewport(0, 0, kImageSize, kImageSize);
  glDisable(GL_DEPTH_TEST);
  const float h = kGroundHalfWidth, z = kGroundZ;
  const std::vector<Vec3> ground = {{-h, -h, z}, {h, -h, z}, {h, h, z},
                                    {-h, -h, z}, {h, h, z},  {-h, h, z}};
  glBindVertexArray(vertex_array(ground));
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(ground.size()));
}

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

bool bind_function_inputs(GLuint program, const nlohmann::json& reflection, GLuint map,
                          const nlohmann::json& values, std::string& log) {
  const nlohmann::json& frag = reflection.at("frag");
  GLuint unit = 0;
  for (const nlohmann::json& texture : frag.value("textures", nlohmann::json::array())) {
    const std::string name = texture.at("name");
    const bool array = texture.at("type").get<std::string>().find("Array") != std::string::npos;
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(array ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, map);
    glBindSampler(unit, sampler_object(texture.at("sampler")));
    glUniform1i(glGetUniformLocation(program, name.c_str()), GLint(unit));
    ++unit;
  }
  const auto value = [&](const nlohmann::json& member) {
    return values.at(member.at("parameter").get<std::string>()).get<std::vector<float>>();
  };
  for (const nlohmann::json& uniform : frag.value("uniforms", nlohmann::json::array())) {
    const std::string name = uniform.at("name");
    // A uniform the function does not read may be gone from the program.
    const GLint location = glGetUniformLocation(program, name.c_str());
    if (location >= 0) glUniform4fv(location, 1, value(uniform).data());
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

GLuint depth_target(int width, int height, int layers) {
  const GLenum target = layers > 0 ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D;
  GLuint map = 0;
  glGenTextures(1, &map);
  glBindTexture(target, map);
  if (layers > 0) {
    glTexImage3D(target, 0, GL_DEPTH_COMPONENT32F, width, height, layers, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT, nullptr);
  } else {
    glTexImage2D(target, 0, GL_DEPTH_COMPONENT32F, width, height, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 nullptr);
  }
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
  GLuint framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  if (layers > 0) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, map, 0, 0);
  } else {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map, 0);
  }
  glDrawBuffer(GL_NONE);
  return map;
}

void picture_target() {
  GLuint colour = 0, picture = 0;
  glGenTextures(1, &colour);
  glBindTexture(GL_TEXTURE_2D, colour);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kImageSize, kImageSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  glGenFramebuffers(1, &picture);
  glBindFramebuffer(GL_FRAMEBUFFER, picture);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
}

std::vector<png_byte> read_channel(int channel, std::string& log) {
  std::vector<png_byte> rgba(std::size_t(kImageSize) * kImageSize * 4);
  glReadPixels(0, 0, kImageSize, kImageSize, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    log = "OpenGL error " + std::to_string(error);
    return {};
  }
  std::vector<png_byte> out(std::size_t(kImageSize) * kImageSize);
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = rgba[4 * k + std::size_t(channel)];
  return out;
}

bool write_png(const std::string& path, const std::vector<png_byte>& grey) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = kImageSize;
  image.height = kImageSize;
  image.format = PNG_FORMAT_GRAY;
  return png_image_write_to_file(&image, path.c_str(), 0, grey.data(), 0, nullptr) != 0;
}

}  // namespace gl_engine
