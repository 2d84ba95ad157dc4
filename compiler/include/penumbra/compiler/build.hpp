// Building a shader library: every pass of every variant for each of its
// targets, written under an output directory with index.json.
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/compiler/shaderlib_source.hpp"
#include "penumbra/compiler/stage.hpp"
#include "penumbra/model/model.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/spirv/reflection.hpp"
#include "penumbra/support/diagnostics.hpp"

namespace penumbra {

// "0.1.0": the version written into index.json's generator field.
std::string_view penumbra_version();

// "penumbra 0.1.0; build <GNU build ID>; glslang 12.0.0; SPIRV-Tools ...":
// the compilers linked into this executable, part of every cache key.
std::string toolchain_id();

// What decides a variant's shaders besides the shaderlib and its targets:
// name, technique, keys, disks and blur weights, as text for cache keys.
std::string variant_identity(const Variant& variant);

// Direct3D bytecode from the HLSL targets' text, by vkd3d-compiler
// 2.1 or newer (scripts/lib/sid-tools.sh installs it).
struct HlslCompilerOptions {
  std::filesystem::path compiler = {};  // vkd3d-compiler to run; empty: text only, no bytecode
  std::chrono::milliseconds timeout{60'000};  // per file; a file still compiling fails its variant
};

struct BuildOptions {
  int jobs = 1;                   // shaders compiled in parallel (penumbra build -j)
  HlslCompilerOptions hlsl = {};  // the bytecode stage; off when hlsl.compiler is empty
  // After a shader fails, compile the rest anyway and report every failure
  // (penumbra build --keep-going); OUT is still written only when all succeed.
  bool keep_going = false;
  // Where shaderlib files are read from (penumbra build --shaderlib DIR).
  std::shared_ptr<const ShaderlibSource> shaderlib = embedded_shaderlib();
  // The content-addressed shader cache (docs/cache.md); empty: none.
  std::filesystem::path cache_dir = {};
  // Called after each shader with (finished, total), from the worker
  // threads but never two at once; empty: no progress reports.
  std::function<void(std::size_t, std::size_t)> progress = {};
};

// Where a build's time went, one row per pipeline stage (penumbra build
// --profile, docs/performance.md): seconds summed over the worker threads.
struct StageTime {
  std::string stage;        // a Stage's name(), "cache" (keying, restoring, storing) or "index"
  double seconds = 0.0;     // thread-seconds spent in it
  std::size_t shaders = 0;  // how many shaders ran it (for "index": variant records written)
};

struct BuildSummary {
  std::size_t variants = 0;  // variants written
  std::size_t files = 0;     // shader files written (text or SPIR-V)
  std::size_t bytecode = 0;  // Direct3D bytecode files written beside the HLSL
  std::size_t cached = 0;    // shader files restored from the cache, not compiled
  // The shaderlib files the built shaders read, as the source's locations
  // (ShaderlibSource::location), sorted and unique: a build's dependencies.
  std::vector<std::string> inputs;
  // Each stage's time, in pipeline order, then the cache's and index.json's;
  // empty for a build the cache's stamp found current.
  std::vector<StageTime> profile;
};

// A kind of folder that penumbra replaces whole, for the messages and the
// file that marks it as penumbra's.
struct OutputKind {
  std::string_view what;     // "library": "... is not a penumbra library"
  std::string_view marker;   // the JSON file whose top-level "generator" is "penumbra ..."
  std::string_view writers;  // "penumbra build or merge": "a library that ... wrote"
};

// OK when `dir` may be replaced by a folder of `kind`: it is missing, an
// empty directory, or one that penumbra wrote (its marker says "generator":
// "penumbra ..."); never a user's file or folder. Errors (bad_input) name
// `dir` and say what is allowed.
Status check_replaceable_directory(const std::filesystem::path& dir, const OutputKind& kind);

// check_replaceable_directory() for a library (index.json, by build or merge).
Status check_output_directory(const std::filesystem::path& out);

// Compiles everything into a staging directory and swaps it into `out_dir`
// only when all of it succeeded: on error `out_dir` is left as it was. No
// variants make a library with none (an empty group of a split build).
// Without keep_going the error is the first failing shader's; with it, every
// failing shader is reported to `diagnostics` as an error and the returned
// error counts them. `diagnostics` is called from the calling thread only.
Result<BuildSummary> build_library(std::span<const Variant> variants,
                                   const std::filesystem::path& out_dir,
                                   const BuildOptions& options,
                                   const DiagnosticConsumer& diagnostics);

// Joins libraries that builds of disjoint parts of one manifest wrote (penumbra
// build --group I/N) into `out_dir`, byte for byte the library one build of
// the whole would write: variants in library order (variant_less), shared
// records numbered as that build numbers them, every file copied. Errors
// (bad_input) name the part: not a library, a variant in two parts, parts
// from different penumbra versions, or a shared file that parts disagree on.
// `out_dir` is replaced only on success.
Result<BuildSummary> merge_libraries(std::span<const std::filesystem::path> parts,
                                     const std::filesystem::path& out_dir);

// One compiled stage, in memory.
struct CompiledStage {
  std::vector<std::uint32_t> spirv;  // for the target (the source of `text`)
  std::string text;                  // target text; empty for spirv
  ShaderInterface interface;
};

struct CompiledPass {
  CompiledStage vert;
  CompiledStage frag;
  PassReflection reflection;  // the target's record, as index.json's reflection.<pass>.<target>
};

// Compiles one pass of one variant for one target without writing files.
Result<CompiledPass> compile_pass(
    const Variant& variant, Target target, PassKind pass,
    std::shared_ptr<const ShaderlibSource> shaderlib = embedded_shaderlib());

// A variant's function form for one text target (docs/function-form.md):
// the includable text and its reflection (bindings, signature, extensions).
struct CompiledFunction {
  std::string text;
  PassReflection reflection;
};

// Compiles `variant`'s function form for `target` without writing files.
// Errors: bad_input for a technique without one (has_function_form()) or a
// target without text (spirv).
Result<CompiledFunction> compile_function(
    const Variant& variant, Target target,
    std::shared_ptr<const ShaderlibSource> shaderlib = embedded_shaderlib());

// The GLSL that one stage of one pass compiles from: its shaderlib source
// with every include and define resolved, as the build's preprocess stage
// makes it, for compiling with other tools (penumbra_bench_build).
Result<std::string> preprocess_shader(
    const Variant& variant, Target target, PassKind pass, ShaderStage stage,
    std::shared_ptr<const ShaderlibSource> shaderlib = embedded_shaderlib());
// The same for `variant`'s function form for `target`.
Result<std::string> preprocess_function(
    const Variant& variant, Target target,
    std::shared_ptr<const ShaderlibSource> shaderlib = embedded_shaderlib());

}  // namespace penumbra
