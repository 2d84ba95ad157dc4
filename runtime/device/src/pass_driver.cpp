#include "penumbra/runtime/pass_driver.hpp"

#include <algorithm>
#include <string>

#include "penumbra/support/minmax_levels.hpp"

namespace penumbra::runtime {
namespace {

std::string pass_name(PassKind pass) {
  return std::string(to_string(pass)) + " pass";
}

// The state one run carries from pass to pass.
class Run {
 public:
  Run(Device& device, const PassPrograms& programs, const PassInputs& inputs)
      : device_(device), programs_(programs), inputs_(inputs) {
    results_.map = inputs.map;
    results_.mip = inputs.mip;
  }

  Status pass(PassKind pass) {
    switch (pass) {
      case PassKind::depth:
        return depth();
      case PassKind::minmax_init:
        return minmax_init();
      case PassKind::minmax_reduce:
        return minmax_reduce();
      default:
        return screen_pass(pass);
    }
  }

  // The levels drawn so far, gathered into the map's mip once the min-max
  // passes end: every pass after them reads the mip, none the levels.
  Status gather_levels() {
    if (gathered_ || results_.levels.empty()) return {};
    gathered_ = true;
    PENUMBRA_TRY_ASSIGN(Texture mip, device_.gather_mip(*results_.map, results_.levels));
    results_.mip = mip;
    return {};
  }

  PassResults take() { return std::move(results_); }

 private:
  Result<Program> program(PassKind pass) const {
    const auto found = programs_.find(pass);
    if (found == programs_.end()) {
      return make_error(Error::Kind::bad_input, pass_name(pass),
                        "the pass list runs it but no program for it was loaded");
    }
    return found->second;
  }

  Result<Texture> map(PassKind pass) const {
    if (!results_.map) {
      return make_error(Error::Kind::bad_input, pass_name(pass),
                        "reads the shadow map, but the list draws none before it and none was "
                        "given");
    }
    return *results_.map;
  }

  // What `pass` reads (PassDescription::reads) of what the run holds; the
  // device fills the constant disks and names what is missing.
  std::vector<Offer> offers(PassKind pass) const {
    std::vector<Offer> out;
    const auto give = [&](TextureId id, const std::optional<Texture>& texture) {
      if (texture) out.push_back({id, *texture});
    };
    for (TextureId id : describe(pass).reads) {
      switch (id) {
        case TextureId::shadow_depth:
        case TextureId::shadow_cmp:
          give(id, results_.map);
          break;
        case TextureId::shadow_minmax:
          give(id, results_.mip);
          break;
        case TextureId::minmax_source:
          if (!results_.levels.empty()) give(id, results_.levels.back());
          break;
        case TextureId::screen_factor:
          if (!results_.screens.empty()) give(id, results_.screens.back().second);
          break;
        case TextureId::receivers:
          give(id, inputs_.receivers);
          break;
        case TextureId::camera_depth:
          give(id, inputs_.camera_depth);
          break;
        case TextureId::scene_colour:
          give(id, inputs_.scene_colour);
          break;
        case TextureId::pcf_disk:
        case TextureId::blocker_disk:
          break;
      }
    }
    return out;
  }

  Result<Texture> draw(Draw draw) {
    PENUMBRA_TRY_ASSIGN(Drawn drawn, device_.draw(draw));
    if (drawn.gpu_ms) results_.gpu_ms = results_.gpu_ms.value_or(0.0) + *drawn.gpu_ms;
    return drawn.target;
  }

  Status depth() {
    PENUMBRA_TRY(check_triangle_list(inputs_.casters, pass_name(PassKind::depth)));
    Draw call;
    call.pass = PassKind::depth;
    PENUMBRA_TRY_ASSIGN(call.program, program(PassKind::depth));
    call.where = pass_name(PassKind::depth);
    call.params = inputs_.params;
    call.width = inputs_.map_width;
    call.height = inputs_.map_height;
    call.triangles = inputs_.casters;
    call.depth_format = inputs_.depth_format;
    PENUMBRA_TRY_ASSIGN(Texture drawn, draw(std::move(call)));
    results_.map = drawn;
    return {};
  }

  // One min-max level into a target of its size; it reads the level below
  // (source_size) and finds its own texel from its target (screen_size).
  Status level(PassKind pass, LevelSize source, LevelSize size) {
    Draw call;
    call.pass = pass;
    PENUMBRA_TRY_ASSIGN(call.program, program(pass));
    call.where = pass_name(pass);
    call.inputs = offers(pass);
    call.params = inputs_.params;
    call.params["source_size"] = size_vec4(source.width, source.height);
    call.params["screen_size"] = size_vec4(size.width, size.height);
    call.width = size.width;
    call.height = size.height;
    PENUMBRA_TRY_ASSIGN(Texture drawn, draw(std::move(call)));
    results_.levels.push_back(drawn);
    return {};
  }

  Status minmax_init() {
    PENUMBRA_TRY_ASSIGN(Texture source, map(PassKind::minmax_init));
    sizes_ = minmax_level_sizes(source.width, source.height);
    results_.levels.clear();
    gathered_ = false;
    return level(PassKind::minmax_init, {source.width, source.height}, sizes_.front());
  }

  Status minmax_reduce() {
    if (results_.levels.empty()) {
      return make_error(Error::Kind::bad_input, pass_name(PassKind::minmax_reduce),
                        "reduces the level below it, but no minmax_init pass ran before it");
    }
    for (std::size_t l = results_.levels.size(); l < sizes_.size(); ++l) {
      PENUMBRA_TRY(level(PassKind::minmax_reduce, sizes_[l - 1], sizes_[l]));
    }
    return {};
  }

  // A full-screen pass over the screen: the receivers', or the camera
  // depth's where there are none.
  Status screen_pass(PassKind pass) {
    PENUMBRA_TRY(gather_levels());
    const std::optional<Texture>& screen =
        inputs_.receivers ? inputs_.receivers : inputs_.camera_depth;
    if (!screen) {
      return make_error(Error::Kind::bad_input, pass_name(pass),
                        "draws over a screen, but neither receivers nor a camera depth was given");
    }
    Draw call;
    call.pass = pass;
    PENUMBRA_TRY_ASSIGN(call.program, program(pass));
    call.where = pass_name(pass);
    call.inputs = offers(pass);
    call.params = inputs_.params;
    call.params["screen_size"] = size_vec4(screen->width, screen->height);
    call.width = screen->width;
    call.height = screen->height;
    PENUMBRA_TRY_ASSIGN(Texture drawn, draw(std::move(call)));
    results_.screens.emplace_back(pass, drawn);
    return {};
  }

  Device& device_;
  const PassPrograms& programs_;
  const PassInputs& inputs_;
  PassResults results_;
  std::vector<LevelSize> sizes_;  // the min-max levels' sizes, once minmax_init ran
  bool gathered_ = false;
};

}  // namespace

Result<FloatImage> Device::read(Texture texture) {
  PENUMBRA_TRY_ASSIGN(std::vector<FloatImage> images, read_all(std::span(&texture, 1)));
  return std::move(images.front());
}

std::optional<Texture> PassResults::screen(PassKind pass) const {
  const auto found = std::ranges::find(screens, pass, &std::pair<PassKind, Texture>::first);
  if (found == screens.end()) return std::nullopt;
  return found->second;
}

Result<PassResults> run_passes(Device& device, std::span<const PassKind> passes,
                               const PassPrograms& programs, const PassInputs& inputs) {
  Run run(device, programs, inputs);
  for (PassKind pass : passes) PENUMBRA_TRY(run.pass(pass));
  PENUMBRA_TRY(run.gather_levels());
  return run.take();
}

const FloatImage* PassOutputs::target(PassKind pass) const {
  const auto found = std::ranges::find(targets, pass, &std::pair<PassKind, FloatImage>::first);
  return found == targets.end() ? nullptr : &found->second;
}

Status upload_screen(Device& device, const ScreenImages& images, std::span<const PassKind> passes,
                     PassInputs& inputs) {
  const auto read = [&](TextureId texture) {
    return std::ranges::any_of(passes, [&](PassKind pass) {
      return std::ranges::find(describe(pass).reads, texture) != describe(pass).reads.end();
    });
  };
  const auto upload = [&](TextureId as, const FloatImage* image,
                          std::optional<Texture>& into) -> Status {
    if (!image || !read(as)) return {};
    PENUMBRA_TRY_ASSIGN(into, device.upload(as, *image));
    return {};
  };
  PENUMBRA_TRY(upload(TextureId::receivers, images.receivers, inputs.receivers));
  PENUMBRA_TRY(upload(TextureId::camera_depth, images.camera_depth, inputs.camera_depth));
  PENUMBRA_TRY(upload(TextureId::scene_colour, images.scene_colour, inputs.scene_colour));
  return {};
}

Result<PassOutputs> run_and_read(Device& device, std::span<const PassKind> passes,
                                 const PassPrograms& programs, const PassInputs& inputs) {
  PENUMBRA_TRY_ASSIGN(PassResults results, run_passes(device, passes, programs, inputs));
  std::vector<Texture> targets;
  for (const auto& [pass, target] : results.screens) targets.push_back(target);
  PENUMBRA_TRY_ASSIGN(std::vector<FloatImage> images, device.read_all(targets));
  PassOutputs out;
  out.gpu_ms = results.gpu_ms;
  for (std::size_t i = 0; i < images.size(); ++i) {
    out.targets.emplace_back(results.screens[i].first, std::move(images[i]));
  }
  return out;
}

Result<Texture> draw_map(Device& device, Program depth,
                         std::span<const std::array<float, 3>> casters, int width, int height,
                         DepthFormat format, const ParamBlock& params) {
  PassInputs inputs;
  inputs.casters = casters;
  inputs.map_width = width;
  inputs.map_height = height;
  inputs.depth_format = format;
  inputs.params = params;
  const PassKind passes[] = {PassKind::depth};
  PENUMBRA_TRY_ASSIGN(PassResults results,
                      run_passes(device, passes, {{PassKind::depth, depth}}, inputs));
  return *results.map;
}

Result<Drawn> draw_surface(Device& device, Program program,
                           std::span<const std::array<float, 3>> triangles, int width, int height,
                           Texture map, std::optional<Texture> mip, const ParamBlock& params) {
  PENUMBRA_TRY(check_triangle_list(triangles, "surface pass"));
  Draw call;
  call.program = program;
  call.where = "surface pass";
  call.inputs = {{TextureId::shadow_depth, map}, {TextureId::shadow_cmp, map}};
  if (mip) call.inputs.push_back({TextureId::shadow_minmax, *mip});
  call.params = params;
  call.width = width;
  call.height = height;
  call.triangles = triangles;
  return device.draw(call);
}

Status check_triangle_list(std::span<const std::array<float, 3>> vertices, std::string_view where) {
  if (vertices.size() % 3 == 0) return {};
  return make_error(Error::Kind::bad_input, std::string(where),
                    std::to_string(vertices.size()) +
                        " vertices are not a whole number of triangles (a triangle list)");
}

std::vector<PassKind> select_passes(std::span<const PassKind> technique_passes, bool draw_depth,
                                    bool deferred) {
  std::vector<PassKind> out;
  for (PassKind pass : technique_passes) {
    if (pass == PassKind::depth && !draw_depth) continue;
    if (pass == (deferred ? PassKind::query : PassKind::deferred)) continue;
    out.push_back(pass);
  }
  return out;
}

void release_all(Device& device, const PassResults& results, const PassInputs& inputs) {
  for (const auto& [pass, target] : results.screens) device.release(target);
  if (results.mip && results.mip != inputs.mip) device.release(*results.mip);
  for (const Texture& level : results.levels) device.release(level);
  if (results.map && results.map != inputs.map) device.release(*results.map);
}

}  // namespace penumbra::runtime
