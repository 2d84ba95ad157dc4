#include "test_programs.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>
#include <tuple>

#include "default_library.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "validation_messages.hpp"

namespace penumbra::test {

std::vector<std::uint32_t> read_spirv(const std::string& name) {
  const std::string path = std::string(PENUMBRA_VULKAN_TEST_SPIRV_DIR) + "/" + name + ".spv";
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) {
    ADD_FAILURE() << "cannot read " << path;
    return {};
  }
  std::vector<std::uint32_t> words(static_cast<std::size_t>(file.tellg()) / sizeof(std::uint32_t));
  file.seekg(0);
  file.read(reinterpret_cast<char*>(words.data()),
            static_cast<std::streamsize>(words.size() * sizeof(std::uint32_t)));
  return words;
}

namespace {

StageCode stage(const std::string& name) {
  StageCode code{read_spirv(name), {}};
  auto iface = reflect(code.spirv);
  if (!iface) {
    ADD_FAILURE() << name << ": " << iface.error().to_string();
    return code;
  }
  code.iface = std::move(*iface);
  return code;
}

// A test program with the reflection of the default variant's pass that
// declares the same resources.
PassProgram program(const std::string& vert, const std::string& frag, const std::string& variant,
                    PassKind pass) {
  PassProgram out;
  out.vert = stage(vert);
  out.frag = stage(frag);
  out.reflection = pass_reflection(variant, pass);
  return out;
}

}  // namespace

ParamBlock make_params(const TestLight& light, int map_w, int map_h, int screen_w, int screen_h) {
  const auto mw = static_cast<float>(map_w);
  const auto mh = static_cast<float>(map_h);
  const auto sw = static_cast<float>(screen_w);
  const auto sh = static_cast<float>(screen_h);
  return {{"shadow_map_size", {mw, mh, 1.0f / mw, 1.0f / mh}},
          {"light",
           {light.light_size, light.frustum_width, light.near_plane,
            light.light_size / light.frustum_width}},
          {"sampling", {2.0f / mw, light.bias, light.depth_scale, 1.0f / light.depth_scale}},
          {"screen_size", {sw, sh, 1.0f / sw, 1.0f / sh}},
          {"source_size", {mw, mh, 1.0f / mw, 1.0f / mh}},
          {"minmax_info", {static_cast<float>(minmax_top_level(map_w, map_h)), 0.0f, 0.0f, 0.0f}}};
}

const CompiledPass* compiled_pass(const std::string& variant, PassKind pass, Target target) {
  static std::map<std::tuple<std::string, PassKind, Target>, CompiledPass> cache;
  const auto key = std::make_tuple(variant, pass, target);
  if (auto it = cache.find(key); it != cache.end()) return &it->second;
  const Variant* found = penumbra::testing::find_default_variant(variant);
  if (!found) {
    ADD_FAILURE() << "no default variant " << variant;
    return nullptr;
  }
  auto compiled = compile_pass(*found, target, pass);
  if (!compiled) {
    ADD_FAILURE() << compiled.error().to_string();
    return nullptr;
  }
  return &cache.emplace(key, std::move(*compiled)).first->second;
}

PassReflection pass_reflection(const std::string& variant, PassKind pass, Target target) {
  const CompiledPass* compiled = compiled_pass(variant, pass, target);
  return compiled ? compiled->reflection : PassReflection{};
}

PassProgram depth_program(const std::string& vert_name) {
  return program(vert_name, "depth.frag", "hard", PassKind::depth);
}

PassProgram compare_program() {
  return program("fullscreen.vert", "compare.frag", "pcss_b16_p16_poisson", PassKind::query);
}

PassProgram point_program() {
  return program("fullscreen.vert", "point.frag", "hard", PassKind::query);
}

PassProgram point_with_cmp_program() {
  return program("fullscreen.vert", "point_with_cmp.frag", "pcss_b16_p16_poisson", PassKind::query);
}

PassProgram minmax_init_program(const std::string& frag_name) {
  return program("fullscreen.vert", frag_name, "backprojection", PassKind::minmax_init);
}

PassProgram minmax_reduce_program() {
  return program("fullscreen.vert", "minmax_reduce.frag", "backprojection",
                 PassKind::minmax_reduce);
}

PassProgram minmax_probe_program() {
  return program("fullscreen.vert", "minmax_probe.frag", "backprojection", PassKind::query);
}

PassProgram unknown_sampler_program() {
  return program("fullscreen.vert", "unknown_sampler.frag", "hard", PassKind::query);
}

std::unique_ptr<Engine> make_engine(bool validation) {
  auto engine = Engine::create({"", validation}, penumbra::testing::fail_on_validation_messages());
  if (!engine) {
    ADD_FAILURE() << engine.error().to_string();
    return nullptr;
  }
  return std::move(*engine);
}

void add_caster_quad(std::vector<std::array<float, 3>>& triangles, const TestLight& light, float u0,
                     float u1, float v0, float v1, float z) {
  // docs/shader-interface.md's u = 0.5 + (x n / z) / Fw solved for x (and v for y).
  const auto x = [&](float u) { return (u - 0.5f) * z * light.frustum_width / light.near_plane; };
  const std::array<float, 3> a{x(u0), x(v0), z};
  const std::array<float, 3> b{x(u1), x(v0), z};
  const std::array<float, 3> c{x(u1), x(v1), z};
  const std::array<float, 3> d{x(u0), x(v1), z};
  triangles.insert(triangles.end(), {a, b, c, a, c, d});
}

FloatImage receivers_row(const std::vector<std::array<float, 3>>& points) {
  FloatImage image(static_cast<int>(points.size()), 1, 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int c = 0; c < 3; ++c) image.at(static_cast<int>(i), 0, c) = points[i][c];
  }
  return image;
}

void EngineWithMapTest::SetUp() {
  engine_ = make_engine();
  ASSERT_NE(engine_, nullptr);
  auto map = engine_->upload_shadow_map(FloatImage(2, 2, 1, 0.5f));
  ASSERT_TRUE(map) << map.error().to_string();
  map_ = *map;
}

Error EngineWithMapTest::failed_query(const PassProgram& program, const ParamBlock& params) {
  auto result = engine_->run_query(program, *map_, FloatImage(2, 2, 3), params);
  EXPECT_FALSE(result);
  return result ? Error{} : result.error();
}

}  // namespace penumbra::test
