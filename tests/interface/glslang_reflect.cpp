#include "glslang_reflect.hpp"

#include <glslang/Include/Types.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <mutex>

namespace penumbra::testing {
namespace {

std::string type_name(const glslang::TType& type) {
  if (type.getBasicType() == glslang::EbtSampler) {
    const glslang::TSampler& sampler = type.getSampler();
    if (sampler.isPureSampler()) return sampler.isShadow() ? "samplerShadow" : "sampler";
    // "sampler2D", "sampler2DShadow", "texture2D", "sampler2DArray", ...
    return sampler.getString().c_str();
  }
  if (type.getBasicType() == glslang::EbtFloat && !type.isMatrix() && !type.isArray()) {
    return type.isVector() ? "vec" + std::to_string(type.getVectorSize()) : "float";
  }
  return type.getCompleteString().c_str();
}

GlslangObject object(const glslang::TObjectReflection& reflected) {
  GlslangObject out;
  out.name = reflected.name;
  out.offset = reflected.offset;
  out.block = reflected.index;
  out.binding = reflected.getBinding();
  out.live = reflected.stages != 0;
  if (const glslang::TType* type = reflected.getType()) {
    out.type = type_name(*type);
    out.components = type->getVectorSize();
    const glslang::TQualifier& qualifier = type->getQualifier();
    if (qualifier.semanticName != nullptr) out.semantic = qualifier.semanticName;
    if (qualifier.hasLocation()) out.location = static_cast<int>(qualifier.layoutLocation);
  }
  return out;
}

}  // namespace

Result<GlslangReflection> glslang_reflect(std::string_view text, ShaderStage stage,
                                          GlslangSource source) {
  static std::once_flag initialized;
  std::call_once(initialized, [] { glslang::InitializeProcess(); });
  const EShLanguage language = stage == ShaderStage::vertex ? EShLangVertex : EShLangFragment;
  glslang::TShader shader(language);
  const std::string source_text(text);
  const char* strings = source_text.c_str();
  shader.setStrings(&strings, 1);
  int messages = EShMsgDefault;
  if (source == GlslangSource::glsl) {
    shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientNone, 0);
  } else {
    shader.setEnvInput(glslang::EShSourceHlsl, language, glslang::EShClientNone, 0);
    shader.setEntryPoint("main");
    messages |= EShMsgReadHlsl;
    if (source == GlslangSource::hlsl_dx9) messages |= EShMsgHlslDX9Compatible;
  }
  // 100: the version of a text without #version; every emitted GLSL text has one.
  if (!shader.parse(GetDefaultResources(), 100, false, static_cast<EShMessages>(messages))) {
    return make_error(Error::Kind::compile, "glslang", shader.getInfoLog());
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(static_cast<EShMessages>(messages))) {
    return make_error(Error::Kind::compile, "glslang", program.getInfoLog());
  }
  // Every member of a live block and every input, live or not: the API
  // reports a live block whole, and attributes by declaration.
  if (!program.buildReflection(EShReflectionAllBlockVariables | EShReflectionIntermediateIO |
                               EShReflectionAllIOVariables)) {
    return make_error(Error::Kind::compile, "glslang", "buildReflection failed");
  }
  GlslangReflection out;
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    out.uniforms.push_back(object(program.getUniform(i)));
  }
  for (int i = 0; i < program.getNumUniformBlocks(); ++i) {
    const glslang::TObjectReflection& block = program.getUniformBlock(i);
    out.blocks.push_back({block.name, block.getBinding(), block.size});
  }
  for (int i = 0; i < program.getNumPipeInputs(); ++i) {
    out.inputs.push_back(object(program.getPipeInput(i)));
  }
  for (int i = 0; i < program.getNumPipeOutputs(); ++i) {
    out.outputs.push_back(object(program.getPipeOutput(i)));
  }
  return out;
}

}  // namespace penumbra::testing
