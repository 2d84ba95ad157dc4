#include "penumbra/verify/gpu_cost.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/compiler/text_frontend.hpp"
#include "penumbra/verify/library_programs.hpp"
#include "scene_fixture.hpp"
#include "scene_passes.hpp"
#include "scene_truths.hpp"

namespace penumbra {
namespace {

constexpr Target kTarget = Target::spirv;

using TimedRun = std::function<Result<std::optional<double>>()>;

// `run` once untimed, then `runs` times; the median of their GPU times.
Result<double> median_ms(const std::string& what, int runs, const TimedRun& run) {
  PENUMBRA_TRY(run());
  std::vector<double> times;
  for (int i = 0; i < std::max(1, runs); ++i) {
    PENUMBRA_TRY_ASSIGN(std::optional<double> ms, run());
    if (!ms) {
      return make_error(Error::Kind::device, what,
                        "the Vulkan device writes no timestamps (timestampValidBits 0), so "
                        "its GPU time cannot be measured");
    }
    times.push_back(*ms);
  }
  std::sort(times.begin(), times.end());
  const std::size_t n = times.size();
  return n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
}

double mean(const FloatImage& image) {
  double sum = 0.0;
  for (float v : image.data) sum += v;
  return image.data.empty() ? 0.0 : sum / double(image.data.size());
}

// The scene drawn by `entry`'s depth pass (the untimed run); with
// `depth_ms`, that pass's median GPU time over `runs` more maps.
Result<SceneFixture> draw_scene(const Library& library, Engine& engine, const LibraryVariant& entry,
                                const PictureScene& scene, int runs, double* depth_ms) {
  PENUMBRA_TRY_ASSIGN(auto depth, load_executable(library, entry, PassKind::depth, kTarget));
  SceneTruths truths;
  PENUMBRA_TRY_ASSIGN(SceneFixture fixture, prepare_scene(engine, truths, depth.program, kTarget,
                                                          scene.scene, scene.receivers));
  if (!depth_ms) return fixture;
  const reference::Scene& s = scene.scene;
  const auto triangles = reference::triangles(s);
  PENUMBRA_TRY_ASSIGN(
      *depth_ms,
      median_ms(entry.variant.name + " depth pass", runs, [&]() -> Result<std::optional<double>> {
        PENUMBRA_TRY_ASSIGN(auto map, engine.render_depth(depth.program, triangles, s.map_width,
                                                          s.map_height, fixture.params));
        return map->depth_gpu_ms();
      }));
  return fixture;
}

const TextureBinding* find_texture(const StageBindings& stage, const std::string& name) {
  for (const TextureBinding& t : stage.textures) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

const PassReflection* spirv_query(const LibraryVariant& entry) {
  const auto pass = entry.reflection.find(PassKind::query);
  if (pass == entry.reflection.end()) return nullptr;
  const auto it = pass->second.find(kTarget);
  return it == pass->second.end() ? nullptr : &it->second;
}

// The fetch-only fragment stage, reading shadow_cmp and receivers where the
// variant's query pass has them.
std::string fetch_only_source(const TextureBinding& cmp, const TextureBinding& receivers,
                              int fetches) {
  const auto layout = [](const TextureBinding& t) {
    return "layout(set = " + std::to_string(t.set.value_or(0)) +
           ", binding = " + std::to_string(t.binding.value_or(0)) + ") ";
  };
  return "#version 450\n" + layout(cmp) + "uniform sampler2DShadow shadow_cmp;\n" +
         layout(receivers) +
         "uniform sampler2D receivers;\n"
         "layout(location = 0) in vec2 screen_uv;\n"
         "layout(location = 0) out vec4 visibility;\n"
         "const int kFetches = " +
         std::to_string(fetches) +
         ";\n"
         "void main() {\n"
         "  vec3 query = textureLod(receivers, screen_uv, 0.0).xyz;\n"
         "  vec2 texel = 1.0 / vec2(textureSize(shadow_cmp, 0));\n"
         "  float lit = 0.0;\n"
         "  for (int i = 0; i < kFetches; ++i) {\n"
         "    vec2 offset = vec2(float(i % 8) - 3.5, float(i / 8) - 3.5) * texel;\n"
         "    lit += textureLod(shadow_cmp, vec3(query.xy + offset, query.z * 0.0625), 0.0);\n"
         "  }\n"
         "  visibility = vec4(lit / float(kFetches), 4.0 * float(kFetches), 0.0, 0.0);\n"
         "}\n";
}

// `like`'s query program with its fragment stage replaced by the fetch-only
// one; its reflection keeps only the two textures that stage reads, with
// their bindings and sampler states.
Result<PassProgram> fetch_only_program(const Library& library, const LibraryVariant& like,
                                       int fetches) {
  PENUMBRA_TRY_ASSIGN(auto query, load_executable(library, like, PassKind::query, kTarget));
  PassProgram program = std::move(query.program);
  StageBindings& frag = program.reflection.frag;
  const TextureBinding* cmp = find_texture(frag, "shadow_cmp");
  const TextureBinding* receivers = find_texture(frag, "receivers");
  if (!cmp || !receivers) {
    return make_error(Error::Kind::bad_input, like.variant.name,
                      "its spirv query pass reads no shadow_cmp (or no receivers); the "
                      "fetch-only shader takes its comparison sampler from a variant that does");
  }
  const std::string source = fetch_only_source(*cmp, *receivers, fetches);
  frag.textures = {*cmp, *receivers};
  frag.blocks.clear();
  frag.uniforms.clear();
  PENUMBRA_TRY_ASSIGN(auto compiled, compile_target_text(Target::glsl450, ShaderStage::fragment,
                                                         source, "fetch_only.frag"));
  PENUMBRA_TRY_ASSIGN(auto iface, reflect(compiled.spirv));
  program.frag = StageCode{std::move(compiled.spirv), std::move(iface)};
  return program;
}

}  // namespace

double gigatexels_per_second(double pixels, double reads_per_pixel, double ms) {
  return ms > 0.0 ? pixels * reads_per_pixel / (ms * 1e-3) * 1e-9 : 0.0;
}

bool reads_comparison_sampler(const LibraryVariant& entry) {
  const PassReflection* query = spirv_query(entry);
  return query && find_texture(query->frag, "shadow_cmp") && find_texture(query->frag, "receivers");
}

Result<GpuCost> measure_gpu_cost(const Library& library, Engine& engine,
                                 const LibraryVariant& entry, const PictureScene& scene,
                                 const GpuCostOptions& options) {
  const Variant& variant = entry.variant;
  GpuCost cost;
  cost.variant = variant.name;
  cost.technique = variant.technique;
  PENUMBRA_TRY_ASSIGN(SceneFixture fixture,
                      draw_scene(library, engine, entry, scene, options.runs, &cost.depth_ms));

  if (uses_minmax_mip(variant.technique)) {
    PENUMBRA_TRY_ASSIGN(auto init, load_executable(library, entry, PassKind::minmax_init, kTarget));
    PENUMBRA_TRY_ASSIGN(auto reduce,
                        load_executable(library, entry, PassKind::minmax_reduce, kTarget));
    PENUMBRA_TRY_ASSIGN(
        cost.mip_ms, median_ms(variant.name + " min-max mip", options.runs,
                               [&]() -> Result<std::optional<double>> {
                                 PENUMBRA_TRY_ASSIGN(
                                     auto mip, engine.build_minmax(*fixture.map, init.program,
                                                                   reduce.program, fixture.params));
                                 return mip.gpu_ms;
                               }));
  }

  // The passes after the mip, timed together (a chain such as screen_blur's too).
  const std::vector<PassKind> passes = scene_passes(entry, /*builds_mip=*/false);
  PENUMBRA_TRY_ASSIGN(LoadedPrograms programs, load_passes(passes, [&](PassKind pass) {
                        return load_executable(library, entry, pass, kTarget);
                      }));
  auto loaded = std::make_shared<const LoadedPrograms>(std::move(programs));
  const TimedRun query = [&engine, &fixture, &cost, &passes,
                          loaded]() -> Result<std::optional<double>> {
    PENUMBRA_TRY_ASSIGN(
        runtime::PassOutputs outputs,
        engine.run_passes(passes, program_map(*loaded), *fixture.map,
                          {.receivers = &fixture.receivers, .scene_colour = &fixture.colour},
                          fixture.params));
    QueryOutput out = final_visibility(outputs);
    cost.visibility = std::move(out.visibility);
    cost.texel_reads = std::move(out.texel_reads);
    return out.gpu_ms;
  };
  PENUMBRA_TRY_ASSIGN(cost.query_ms, median_ms(variant.name + " query pass", options.runs, query));
  cost.texel_reads_per_pixel = mean(cost.texel_reads);
  return cost;
}

Result<FetchCeiling> measure_fetch_ceiling(const Library& library, Engine& engine,
                                           const LibraryVariant& like, const PictureScene& scene,
                                           int fetches, const GpuCostOptions& options) {
  PENUMBRA_TRY_ASSIGN(PassProgram program, fetch_only_program(library, like, fetches));
  PENUMBRA_TRY_ASSIGN(SceneFixture fixture, draw_scene(library, engine, like, scene, 0, nullptr));
  FetchCeiling ceiling{like.variant.name, fetches, 0.0, 0.0};
  PENUMBRA_TRY_ASSIGN(
      ceiling.query_ms,
      median_ms("the fetch-only shader", options.runs, [&]() -> Result<std::optional<double>> {
        PENUMBRA_TRY_ASSIGN(auto out, engine.run_query_output(program, *fixture.map,
                                                              fixture.receivers, fixture.params));
        ceiling.texel_reads_per_pixel = mean(out.texel_reads);
        return out.gpu_ms;
      }));
  return ceiling;
}

}  // namespace penumbra
