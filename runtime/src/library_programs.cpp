#include "penumbra/runtime/library_programs.hpp"

#include <cmath>

namespace penumbra {
namespace {

Result<StageCode> load_stage(const std::filesystem::path& path) {
  auto words = read_spirv_file(path);
  if (!words) return words.error();
  auto iface = reflect(*words);
  if (!iface) return make_error(Error::Kind::compile, path.string(), iface.error().message);
  return StageCode{std::move(*words), std::move(*iface)};
}

}  // namespace

Result<PassProgram> load_program(const Library& library, const LibraryVariant& variant,
                                 PassKind pass, Target target) {
  const auto by_pass = variant.passes.find(pass);
  const auto files = by_pass == variant.passes.end() ? nullptr : &by_pass->second;
  if (!files || !files->contains(target)) {
    return make_error(Error::Kind::bad_input, variant.variant.name,
                      "the library has no " + std::string(to_string(pass)) + " pass for target " +
                          std::string(to_string(target)));
  }
  const PassFiles& pass_files = files->at(target);
  auto vert = load_stage(library.root / pass_files.vert);
  if (!vert) return vert.error();
  auto frag = load_stage(library.root / pass_files.frag);
  if (!frag) return frag.error();
  return PassProgram{std::move(*vert), std::move(*frag)};
}

float depth_scale_for(double max_z) {
  const int exponent = max_z > 1.0 ? static_cast<int>(std::ceil(std::log2(max_z))) : 0;
  return std::ldexp(1.0f, -exponent);
}

ParamBlock shadow_params(const reference::LightParams& light, const ParamSizes& sizes,
                         float depth_scale) {
  const auto f = [](double value) { return static_cast<float>(value); };
  const float map_w = static_cast<float>(sizes.map_width);
  const float map_h = static_cast<float>(sizes.map_height);
  const float screen_w = static_cast<float>(sizes.screen_width);
  const float screen_h = static_cast<float>(sizes.screen_height);
  return {
      {"shadow_map_size", {map_w, map_h, 1.0f / map_w, 1.0f / map_h}},
      {"light",
       {f(light.light_world_size), f(light.frustum_width), f(light.near_plane),
        f(light.light_size_uv())}},
      {"sampling",
       {f(light.filter_radius(sizes.map_width)), f(light.bias), depth_scale, 1.0f / depth_scale}},
      {"screen_size", {screen_w, screen_h, 1.0f / screen_w, 1.0f / screen_h}},
  };
}

}  // namespace penumbra
