#include "penumbra/verify/library_programs.hpp"

#include <algorithm>

#include "penumbra/compiler/targets.hpp"
#include "penumbra/compiler/text_frontend.hpp"
#include "penumbra/library/pass_files.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra {
namespace {

Result<StageCode> reflected(std::vector<std::uint32_t> spirv, const std::string& name) {
  auto iface = reflect(spirv);
  if (!iface) return make_error(Error::Kind::compile, name, iface.error().message);
  return StageCode{std::move(spirv), std::move(*iface)};
}

// Compiles one stage's emitted text with the target's front end.
Result<StageCode> text_stage(const Library& library, const LibraryVariant& variant, PassKind pass,
                             Target target, ShaderStage stage, Execution& execution) {
  auto path = pass_stage_path(library, variant, pass, target, stage);
  if (!path) return path.error();
  auto text = read_file(*path);
  if (!text) return text.error();
  return compile_text_stage(target, stage, *text, path->string(), execution);
}

}  // namespace

Result<StageCode> compile_text_stage(Target target, ShaderStage stage, std::string_view text,
                                     const std::string& name, Execution& execution) {
  auto compiled = compile_target_text(target, stage, text, name);
  if (!compiled) return compiled.error();
  execution.front_end = compiled->front_end;
  for (const std::string& shim : compiled->shims) {
    if (std::find(execution.shims.begin(), execution.shims.end(), shim) == execution.shims.end()) {
      execution.shims.push_back(shim);
    }
  }
  return reflected(std::move(compiled->spirv), name);
}

Result<StageCode> compile_bytecode_stage(const BytecodeTranslator& translator, Target target,
                                         ShaderStage stage, const std::string& text,
                                         const std::string& name, Execution& execution) {
  PENUMBRA_TRY_ASSIGN(FrontEndResult translated,
                      compile_hlsl_to_spirv(translator, target, stage, text, name));
  execution.front_end = translated.front_end;
  return reflected(std::move(translated.spirv), name);
}

Result<ExecutableProgram> load_executable(const Library& library, const LibraryVariant& variant,
                                          PassKind pass, Target target) {
  ExecutableProgram out;
  out.program.target = target;
  PENUMBRA_TRY_ASSIGN(out.program.reflection, pass_reflection(variant, pass, target));
  if (target == Target::spirv) {
    for (ShaderStage stage : {ShaderStage::vertex, ShaderStage::fragment}) {
      auto path = pass_stage_path(library, variant, pass, target, stage);
      if (!path) return path.error();
      auto words = read_spirv_file(*path);
      if (!words) return words.error();
      auto code = reflected(std::move(*words), path->string());
      if (!code) return code.error();
      (stage == ShaderStage::vertex ? out.program.vert : out.program.frag) = std::move(*code);
    }
    out.execution.front_end = "SPIR-V as built";
    return out;
  }
  auto vert = text_stage(library, variant, pass, target, ShaderStage::vertex, out.execution);
  if (!vert) return vert.error();
  auto frag = text_stage(library, variant, pass, target, ShaderStage::fragment, out.execution);
  if (!frag) return frag.error();
  out.program.vert = std::move(*vert);
  out.program.frag = std::move(*frag);
  // HLSL flips clip-space y for Direct3D's viewport; GLSL writes OpenGL's
  // clip z in [-w, w]. The engine reproduces each API's convention.
  out.program.d3d_viewport = traits(target).is_hlsl;
  out.program.gl_clip_depth = !traits(target).is_hlsl;
  return out;
}

Result<ExecutableProgram> load_bytecode_executable(const Library& library,
                                                   const LibraryVariant& variant, PassKind pass,
                                                   Target target,
                                                   const BytecodeTranslator& translator) {
  ExecutableProgram out;
  out.program.target = target;
  PENUMBRA_TRY_ASSIGN(out.program.reflection, pass_reflection(variant, pass, target));
  auto files = pass_files(variant, pass, target);
  if (!files) return files.error();
  std::vector<std::string> profiles;
  for (ShaderStage stage : {ShaderStage::vertex, ShaderStage::fragment}) {
    const bool vertex = stage == ShaderStage::vertex;
    const std::optional<BytecodeFile>& file =
        vertex ? (*files)->vert_bytecode : (*files)->frag_bytecode;
    if (!file) {
      return make_error(Error::Kind::bad_input, variant.variant.name,
                        "index.json lists no " + std::string(to_string(target)) +
                            " bytecode for the " + std::string(to_string(pass)) + " pass's " +
                            (vertex ? "vertex" : "fragment") +
                            " stage (a library built without --hlsl-compiler)");
    }
    auto translated = translate_bytecode(translator, target, stage, library.root / file->path);
    if (!translated) return translated.error();
    out.execution.front_end = translated->front_end;
    profiles.push_back(file->profile);
    auto code = reflected(std::move(translated->spirv), file->path);
    if (!code) return code.error();
    (vertex ? out.program.vert : out.program.frag) = std::move(*code);
  }
  out.execution.front_end += " (" + profiles[0] + ", " + profiles[1] + ")";
  // The bytecode flips y as the HLSL text it was compiled from does.
  out.program.d3d_viewport = true;
  out.program.d3d_bytecode = true;
  return out;
}

Result<MinmaxBuild> build_library_minmax(Engine& engine, const Library& library,
                                         const LibraryVariant& variant, Target target,
                                         ShadowMap& map, const ParamBlock& params) {
  PENUMBRA_TRY_ASSIGN(const ExecutableProgram init,
                      load_executable(library, variant, PassKind::minmax_init, target));
  PENUMBRA_TRY_ASSIGN(const ExecutableProgram reduce,
                      load_executable(library, variant, PassKind::minmax_reduce, target));
  return engine.build_minmax(map, init.program, reduce.program, params);
}

Result<LoadedPrograms> load_passes(std::span<const PassKind> passes, const PassLoader& load) {
  LoadedPrograms loaded;
  for (PassKind pass : passes) {
    PENUMBRA_TRY_ASSIGN(ExecutableProgram program, load(pass));
    loaded.emplace(pass, std::move(program));
  }
  return loaded;
}

PassProgramMap program_map(const LoadedPrograms& loaded) {
  PassProgramMap programs;
  for (const auto& [pass, program] : loaded) programs.emplace(pass, &program.program);
  return programs;
}

}  // namespace penumbra
