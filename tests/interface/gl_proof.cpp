// Proves the glsl330, glsl450 and essl300 reflections by Mesa's OpenGL
// driver: each pass's two emitted files compiled and linked in an OpenGL 4.5
// core context (GLSL 3.30 and 4.50) or an OpenGL ES 3.0 context (ESSL
// 3.00), and the program asked what an engine asks, per stage
// (GL_REFERENCED_BY_*): glGetActiveUniform names and types, sampler units
// (glGetUniformiv: the layout binding, or 0 where the text has none),
// uniform blocks (name, GL_UNIFORM_BLOCK_BINDING, data size, member
// GL_UNIFORM_OFFSET), glGetAttribLocation of each attribute and the
// location of each fragment output. GL names must be exactly the
// reflection's ("params.light", "ShadowParams.light"). The per-stage and
// output queries are program interface queries (OpenGL 4.3, OpenGL ES 3.1):
// Mesa gives an ES 3.2 context where 3.0 is asked for, and compiles the
// text as the ESSL 3.00 it declares.

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <map>
#include <set>
#include <tuple>

#include "egl_context.hpp"
#include "proof.hpp"

namespace penumbra::testing {
namespace {

// GL reports binding 0 where the text gives none.
constexpr FactStyle kStyle{.with_set = false, .member_sizes = false, .unset_binding = 0u};

std::string gl_type(GLenum type) {
  switch (type) {
    case GL_FLOAT:
      return "float";
    case GL_FLOAT_VEC2:
      return "vec2";
    case GL_FLOAT_VEC3:
      return "vec3";
    case GL_FLOAT_VEC4:
      return "vec4";
    case GL_SAMPLER_2D:
      return "sampler2D";
    case GL_SAMPLER_2D_SHADOW:
      return "sampler2DShadow";
    case GL_SAMPLER_2D_ARRAY:
      return "sampler2DArray";
    case GL_SAMPLER_2D_ARRAY_SHADOW:
      return "sampler2DArrayShadow";
    default:
      return "GL type " + std::to_string(type);
  }
}

GLint float_components(GLenum type) {
  switch (type) {
    case GL_FLOAT:
      return 1;
    case GL_FLOAT_VEC2:
      return 2;
    case GL_FLOAT_VEC3:
      return 3;
    case GL_FLOAT_VEC4:
      return 4;
    default:
      return 0;
  }
}

// The stages that reference resource `index` of `interface`: "vert", "frag".
std::vector<std::string_view> referencing_stages(GLuint program, GLenum interface, GLuint index) {
  const GLenum properties[] = {GL_REFERENCED_BY_VERTEX_SHADER, GL_REFERENCED_BY_FRAGMENT_SHADER};
  GLint referenced[2] = {};
  glGetProgramResourceiv(program, interface, index, 2, properties, 2, nullptr, referenced);
  std::vector<std::string_view> stages;
  if (referenced[0]) stages.push_back("vert");
  if (referenced[1]) stages.push_back("frag");
  return stages;
}

std::string resource_name(GLuint program, GLenum interface, GLuint index) {
  char name[256] = {};
  glGetProgramResourceName(program, interface, index, sizeof name, nullptr, name);
  return name;
}

Result<GLuint> compiled(GLenum kind, const std::string& text) {
  const GLuint shader = glCreateShader(kind);
  const char* source = text.c_str();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  char log[4096] = {};
  glGetShaderInfoLog(shader, sizeof log, nullptr, log);
  glDeleteShader(shader);
  return make_error(Error::Kind::compile, kind == GL_VERTEX_SHADER ? "vert" : "frag",
                    std::string("the driver rejects it: ") + log);
}

void report_uniforms(GLuint program, Facts& facts) {
  GLint count = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  for (GLuint i = 0; i < static_cast<GLuint>(count); ++i) {
    char name[256] = {};
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(program, i, sizeof name, nullptr, &size, &type, name);
    GLint block = -1;
    GLint offset = -1;
    glGetActiveUniformsiv(program, 1, &i, GL_UNIFORM_BLOCK_INDEX, &block);
    glGetActiveUniformsiv(program, 1, &i, GL_UNIFORM_OFFSET, &offset);
    if (block >= 0) {
      const auto index = static_cast<GLuint>(block);
      for (std::string_view stage : referencing_stages(program, GL_UNIFORM_BLOCK, index)) {
        facts[std::string(stage) + " block " + resource_name(program, GL_UNIFORM_BLOCK, index) +
              " member " + name] =
            member_text(kStyle, gl_type(type), static_cast<std::uint32_t>(offset), 0);
      }
      continue;
    }
    const bool shadow = type == GL_SAMPLER_2D_SHADOW || type == GL_SAMPLER_2D_ARRAY_SHADOW;
    const bool sampler = shadow || type == GL_SAMPLER_2D || type == GL_SAMPLER_2D_ARRAY;
    GLint unit = -1;
    if (sampler) glGetUniformiv(program, glGetUniformLocation(program, name), &unit);
    for (std::string_view stage : referencing_stages(program, GL_UNIFORM, i)) {
      if (sampler) {
        facts[std::string(stage) + " texture " + name] =
            slot_text(kStyle, std::nullopt, static_cast<std::uint32_t>(unit)) + ", " +
            texture_text(gl_type(type), shadow);
      } else {
        facts[std::string(stage) + " uniform " + name] = gl_type(type);
      }
    }
  }
}

void report_blocks(GLuint program, Facts& facts) {
  GLint count = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCKS, &count);
  for (GLuint i = 0; i < static_cast<GLuint>(count); ++i) {
    char name[256] = {};
    glGetActiveUniformBlockName(program, i, sizeof name, nullptr, name);
    GLint binding = -1;
    GLint size = 0;
    glGetActiveUniformBlockiv(program, i, GL_UNIFORM_BLOCK_BINDING, &binding);
    glGetActiveUniformBlockiv(program, i, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    for (std::string_view stage : referencing_stages(program, GL_UNIFORM_BLOCK, i)) {
      facts[std::string(stage) + " block " + name] =
          slot_text(kStyle, std::nullopt, static_cast<std::uint32_t>(binding)) + ", " +
          std::to_string(size) + " bytes";
    }
  }
}

void report_inputs_and_outputs(GLuint program, Facts& facts) {
  GLint count = 0;
  glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
  for (GLuint i = 0; i < static_cast<GLuint>(count); ++i) {
    char name[256] = {};
    GLint size = 0;
    GLenum type = 0;
    glGetActiveAttrib(program, i, sizeof name, nullptr, &size, &type, name);
    const GLint components = float_components(type);
    facts[std::string("vert input ") + name] = input_text(
        static_cast<std::uint32_t>(glGetAttribLocation(program, name)),
        static_cast<std::uint32_t>(components), components > 0 ? "GL_FLOAT" : gl_type(type));
  }
  glGetProgramInterfaceiv(program, GL_PROGRAM_OUTPUT, GL_ACTIVE_RESOURCES, &count);
  for (GLuint i = 0; i < static_cast<GLuint>(count); ++i) {
    const std::string name = resource_name(program, GL_PROGRAM_OUTPUT, i);
    if (name.starts_with("gl_")) continue;  // gl_FragDepth: no render target
    facts["frag output " + name] = "location " + std::to_string(glGetProgramResourceLocation(
                                                     program, GL_PROGRAM_OUTPUT, name.c_str()));
  }
}

// What the driver reports of the program linked from `vert` and `frag`;
// each pair is linked once per process.
Result<Facts> driver_facts(GlApi api, const std::string& vert, const std::string& frag) {
  static std::map<std::tuple<GlApi, std::string, std::string>, Facts> linked;
  const auto key = std::make_tuple(api, vert, frag);
  if (const auto found = linked.find(key); found != linked.end()) return found->second;
  PENUMBRA_TRY(EglContext::current(api));
  PENUMBRA_TRY_ASSIGN(const GLuint vertex, compiled(GL_VERTEX_SHADER, vert));
  auto fragment = compiled(GL_FRAGMENT_SHADER, frag);
  if (!fragment) {
    glDeleteShader(vertex);
    return fragment.error();
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, *fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(*fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[4096] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    return make_error(Error::Kind::compile, "link", std::string("the driver rejects it: ") + log);
  }
  Facts facts;
  report_uniforms(program, facts);
  report_blocks(program, facts);
  report_inputs_and_outputs(program, facts);
  glDeleteProgram(program);
  return linked.emplace(key, std::move(facts)).first->second;
}

}  // namespace

Status prove_mesa_gl(const Library& library, const LibraryVariant& variant, PassKind pass,
                     Target target) {
  PENUMBRA_TRY_ASSIGN(const PassReflection* reflection, reflection_of(variant, pass, target));
  PENUMBRA_TRY_ASSIGN(const std::string vert,
                      read_pass_file(library, variant, pass, target, ShaderStage::vertex));
  PENUMBRA_TRY_ASSIGN(const std::string frag,
                      read_pass_file(library, variant, pass, target, ShaderStage::fragment));
  const GlApi api = target == Target::essl300 ? GlApi::es : GlApi::desktop;
  auto reported = driver_facts(api, vert, frag);
  if (!reported) return proof_error(variant, pass, target, reported.error().to_string());
  const Facts expected = reflected_facts(*reflection, kStyle);
  return compare_facts(variant, pass, target,
                       api == GlApi::es ? "Mesa's OpenGL ES" : "Mesa's OpenGL", expected,
                       *reported);
}

}  // namespace penumbra::testing
