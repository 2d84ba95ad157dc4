#include "penumbra/gl/engine.hpp"

#include <utility>

#include "context_info.hpp"
#include "device_selection.hpp"
#include "gl_device.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/support/image_checks.hpp"
#include "textures.hpp"

namespace penumbra {

namespace gl {

// What an engine owns: the context (and through it the display). Each call
// creates and deletes its own objects.
struct Context {
  EglContext egl;
  GlInfo info;
};

namespace {

// The passes before `pass` that build the mip it reads, loaded on `device`:
// only what the driver reports active decides, so min-max passes given to a
// program that does not read the mip are neither required nor compiled.
Result<std::vector<PassKind>> minmax_for(GlDevice& device, runtime::Program pass,
                                         const std::optional<GlMinmaxPasses>& minmax,
                                         runtime::PassPrograms& programs) {
  const PassProgram& prepared = device.program(pass);
  if (!prepared.reads(TextureId::shadow_minmax)) return std::vector<PassKind>{};
  if (!minmax) {
    return make_error(Error::Kind::bad_input, prepared.where,
                      "it reads shadow_minmax, the shadow map's min-max mip, but no "
                      "minmax_init and minmax_reduce passes were given to build it");
  }
  PENUMBRA_TRY_ASSIGN(programs[PassKind::minmax_init],
                      device.load(minmax->init, PassKind::minmax_init));
  PENUMBRA_TRY_ASSIGN(programs[PassKind::minmax_reduce],
                      device.load(minmax->reduce, PassKind::minmax_reduce));
  return std::vector<PassKind>{PassKind::minmax_init, PassKind::minmax_reduce};
}

Status check_two_channels(const PassProgram& pass) {
  if (pass.target_format->channels >= 2) return {};
  return make_error(Error::Kind::bad_input, pass.where,
                    "its render target is " + std::string(pass.target_format->name()) +
                        "; the query writes (visibility, texel reads), two channels");
}

// The checks of what a call gives: the map, and the screen images.
Status check_images(const FloatImage& normalized_depth, const runtime::ScreenImages& images) {
  PENUMBRA_TRY(images.receivers ? check_query_inputs(normalized_depth, *images.receivers)
                                : check_shadow_map(normalized_depth));
  if (images.camera_depth) PENUMBRA_TRY(check_shadow_map(*images.camera_depth));
  if (images.scene_colour && images.receivers) {
    PENUMBRA_TRY(check_scene_colour(*images.scene_colour, *images.receivers));
  }
  return {};
}

// `passes`, loaded on `device` as `programs`, on the map over the screen
// `images` gives, every screen target read back.
Result<runtime::PassOutputs> on_map(GlDevice& device, std::span<const PassKind> passes,
                                    const runtime::PassPrograms& programs,
                                    const FloatImage& normalized_depth, DepthFormat map_format,
                                    const runtime::ScreenImages& images, const ParamBlock& params) {
  runtime::PassInputs inputs;
  PENUMBRA_TRY_ASSIGN(inputs.map, device.upload_map(normalized_depth, map_format));
  PENUMBRA_TRY(runtime::upload_screen(device, images, passes, inputs));
  inputs.params = params;
  return runtime::run_and_read(device, passes, programs, inputs);
}

// A query's or a deferred pass's (visibility, texel reads), split.
GlQueryOutput visibility_of(const runtime::PassOutputs& outputs) {
  const FloatImage& target = outputs.targets.front().second;
  return GlQueryOutput{channel(target, 0), channel(target, 1)};
}

// `pass` over the map at the screen `images` gives, after the mip when it
// reads it.
Result<GlQueryOutput> run_screen(const GlPass& text, PassKind kind,
                                 const std::optional<GlMinmaxPasses>& minmax,
                                 const FloatImage& normalized_depth, DepthFormat map_format,
                                 const runtime::ScreenImages& images, const ParamBlock& params) {
  GlDevice device;
  runtime::PassPrograms programs;
  PENUMBRA_TRY_ASSIGN(programs[kind], device.load(text, kind));
  PENUMBRA_TRY(check_two_channels(device.program(programs[kind])));
  PENUMBRA_TRY_ASSIGN(std::vector<PassKind> passes,
                      minmax_for(device, programs[kind], minmax, programs));
  passes.push_back(kind);
  PENUMBRA_TRY_ASSIGN(
      runtime::PassOutputs outputs,
      on_map(device, passes, programs, normalized_depth, map_format, images, params));
  return visibility_of(outputs);
}

}  // namespace

}  // namespace gl

Result<std::unique_ptr<GlEngine>> GlEngine::create(const GlEngineOptions& options,
                                                   DiagnosticConsumer diagnostics) {
  auto opened = gl::open_context(options.device);
  if (!opened) return opened.error();
  GlInfo info;
  {
    auto current = opened->context.make_current();
    if (!current) return current.error();
    info = gl::current_context_info();
  }
  if (diagnostics) {
    diagnostics(
        {Severity::note, "OpenGL", info.renderer + ", " + info.version + " on " + opened->display});
  }
  auto context =
      std::make_unique<gl::Context>(gl::Context{std::move(opened->context), std::move(info)});
  return std::unique_ptr<GlEngine>(new GlEngine(std::move(context)));
}

GlEngine::GlEngine(std::unique_ptr<gl::Context> context) : context_(std::move(context)) {}

GlEngine::~GlEngine() = default;

const GlInfo& GlEngine::info() const {
  return context_->info;
}

Result<GlQueryOutput> GlEngine::run_query(const GlQueryPasses& passes,
                                          const FloatImage& normalized_depth,
                                          const FloatImage& receivers, const ParamBlock& params,
                                          DepthFormat map_format) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  PENUMBRA_TRY(gl::check_query_inputs(normalized_depth, receivers));
  return gl::run_screen(passes.query, PassKind::query, passes.minmax, normalized_depth, map_format,
                        {.receivers = &receivers}, params);
}

Result<GlQueryOutput> GlEngine::run_deferred(const GlPass& deferred,
                                             const FloatImage& normalized_depth,
                                             const FloatImage& camera_depth,
                                             const ParamBlock& params, DepthFormat map_format,
                                             const std::optional<GlMinmaxPasses>& minmax) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  PENUMBRA_TRY(gl::check_shadow_map(normalized_depth));
  PENUMBRA_TRY(gl::check_shadow_map(camera_depth));
  return gl::run_screen(deferred, PassKind::deferred, minmax, normalized_depth, map_format,
                        {.camera_depth = &camera_depth}, params);
}

Result<FloatImage> GlEngine::run_surface(const GlPass& surface,
                                         std::span<const std::array<float, 3>> triangles,
                                         const FloatImage& normalized_depth, int width, int height,
                                         const ParamBlock& params, DepthFormat map_format,
                                         const std::optional<GlMinmaxPasses>& minmax) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  PENUMBRA_TRY(runtime::check_triangle_list(triangles, "surface pass"));
  PENUMBRA_TRY(gl::check_shadow_map(normalized_depth));
  gl::GlDevice device;
  PENUMBRA_TRY_ASSIGN(runtime::Program program, device.load_surface(surface, "surface pass"));
  runtime::PassPrograms programs;
  PENUMBRA_TRY_ASSIGN(std::vector<PassKind> passes,
                      gl::minmax_for(device, program, minmax, programs));
  runtime::PassInputs inputs;
  PENUMBRA_TRY_ASSIGN(inputs.map, device.upload_map(normalized_depth, map_format));
  inputs.params = params;
  PENUMBRA_TRY_ASSIGN(runtime::PassResults built,
                      runtime::run_passes(device, passes, programs, inputs));
  PENUMBRA_TRY_ASSIGN(runtime::Drawn drawn,
                      runtime::draw_surface(device, program, triangles, width, height, *inputs.map,
                                            built.mip, params));
  return device.read(drawn.target);
}

Result<std::vector<FloatImage>> GlEngine::build_minmax(const GlMinmaxPasses& passes,
                                                       const FloatImage& normalized_depth,
                                                       const ParamBlock& params) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  gl::GlDevice device;
  runtime::PassPrograms programs;
  PENUMBRA_TRY_ASSIGN(programs[PassKind::minmax_init],
                      device.load(passes.init, PassKind::minmax_init));
  PENUMBRA_TRY_ASSIGN(programs[PassKind::minmax_reduce],
                      device.load(passes.reduce, PassKind::minmax_reduce));
  runtime::PassInputs inputs;
  PENUMBRA_TRY_ASSIGN(inputs.map, device.upload_map(normalized_depth, DepthFormat::d32_float));
  inputs.params = params;
  const PassKind list[] = {PassKind::minmax_init, PassKind::minmax_reduce};
  PENUMBRA_TRY_ASSIGN(runtime::PassResults results,
                      runtime::run_passes(device, list, programs, inputs));
  std::vector<FloatImage> levels;
  for (runtime::Texture level : results.levels) {
    PENUMBRA_TRY_ASSIGN(FloatImage read, device.read(level));
    levels.push_back(std::move(read));
  }
  return levels;
}

Result<runtime::PassOutputs> GlEngine::run_passes(std::span<const PassKind> passes,
                                                  const std::map<PassKind, GlPass>& programs,
                                                  const FloatImage& normalized_depth,
                                                  const runtime::ScreenImages& images,
                                                  const ParamBlock& params,
                                                  DepthFormat map_format) {
  auto current = context_->egl.make_current();
  if (!current) return current.error();
  PENUMBRA_TRY(gl::check_images(normalized_depth, images));
  gl::GlDevice device;
  runtime::PassPrograms loaded;
  for (PassKind pass : passes) {
    const auto found = programs.find(pass);
    if (found == programs.end() || loaded.contains(pass)) continue;  // the driver names it
    PENUMBRA_TRY_ASSIGN(loaded[pass], device.load(found->second, pass));
    if (pass == PassKind::query || pass == PassKind::deferred) {
      PENUMBRA_TRY(gl::check_two_channels(device.program(loaded[pass])));
    }
  }
  return gl::on_map(device, passes, loaded, normalized_depth, map_format, images, params);
}

}  // namespace penumbra
