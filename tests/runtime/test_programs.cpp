#include "test_programs.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "penumbra/support/minmax_levels.hpp"

namespace penumbra::test {

std::vector<std::uint32_t> read_spirv(const std::string& name) {
  const std::string path = std::string(PENUMBRA_RUNTIME_TEST_SPIRV_DIR) + "/" + name + ".spv";
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

// shaders/params.glsl: six std140 vec4 members.
UniformBlock shadow_params() {
  return {"ShadowParams",
          "params",
          0,
          0,
          96,
          {{"shadow_map_size", 0, 16},
           {"light", 16, 16},
           {"sampling", 32, 16},
           {"screen_size", 48, 16},
           {"source_size", 64, 16},
           {"minmax_info", 80, 16}}};
}

StageCode fullscreen_vert() {
  ShaderInterface iface;
  iface.stage = ShaderStage::vertex;
  iface.inputs = {{"position", 0, 2}};
  iface.builtin_outputs = {"Position", "PointSize", "ClipDistance", "CullDistance"};
  return {read_spirv("fullscreen.vert"), iface};
}

StageCode query_frag(const std::string& name, std::vector<SampledImage> images) {
  ShaderInterface iface;
  iface.stage = ShaderStage::fragment;
  iface.uniform_blocks = {shadow_params()};
  iface.sampled_images = std::move(images);
  iface.outputs = {{"visibility", 0, 4}};
  return {read_spirv(name), iface};
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

PassProgram depth_program(const std::string& vert_name) {
  ShaderInterface vert;
  vert.stage = ShaderStage::vertex;
  vert.uniform_blocks = {shadow_params()};
  vert.inputs = {{"position", 0, 3}};
  vert.outputs = {{"light_z", 0, 1}};
  vert.builtin_outputs = {"Position", "PointSize", "ClipDistance", "CullDistance"};
  ShaderInterface frag;
  frag.stage = ShaderStage::fragment;
  frag.uniform_blocks = {shadow_params()};
  frag.inputs = {{"light_z", 0, 1}};
  frag.outputs = {{"depth_out", 0, 1}};
  frag.builtin_outputs = {"FragDepth"};
  return {{read_spirv(vert_name), vert}, {read_spirv("depth.frag"), frag}};
}

PassProgram compare_program() {
  return {fullscreen_vert(), query_frag("compare.frag", {{"shadow_depth", 0, 1, false},
                                                         {"shadow_cmp", 0, 2, true},
                                                         {"receivers", 0, 3, false}})};
}

PassProgram point_program() {
  return {fullscreen_vert(),
          query_frag("point.frag", {{"shadow_depth", 0, 1, false}, {"receivers", 0, 3, false}})};
}

PassProgram point_with_cmp_program() {
  return {fullscreen_vert(), query_frag("point_with_cmp.frag", {{"shadow_depth", 0, 1, false},
                                                                {"shadow_cmp", 0, 2, true},
                                                                {"receivers", 0, 3, false}})};
}

PassProgram minmax_init_program(const std::string& frag_name) {
  StageCode frag = query_frag(frag_name, {{"shadow_depth", 0, 1, false}});
  frag.iface.outputs = {{"minmax", 0, 4}};
  return {fullscreen_vert(), std::move(frag)};
}

PassProgram minmax_reduce_program() {
  StageCode frag = query_frag("minmax_reduce.frag", {{"minmax_source", 0, 5, false}});
  frag.iface.outputs = {{"minmax", 0, 4}};
  return {fullscreen_vert(), std::move(frag)};
}

PassProgram minmax_probe_program() {
  return {fullscreen_vert(), query_frag("minmax_probe.frag", {{"receivers", 0, 3, false},
                                                              {"shadow_minmax", 0, 4, false}})};
}

PassProgram unknown_sampler_program() {
  PassProgram program{fullscreen_vert(),
                      query_frag("unknown_sampler.frag", {{"shadow_mapp", 0, 1, false}})};
  program.frag.iface.uniform_blocks.clear();
  return program;
}

std::unique_ptr<Engine> make_engine(bool validation) {
  auto engine = Engine::create({"", validation}, ignore_diagnostics());
  if (!engine) {
    ADD_FAILURE() << engine.error().to_string();
    return nullptr;
  }
  return std::move(*engine);
}

void add_caster_quad(std::vector<std::array<float, 3>>& triangles, const TestLight& light, float u0,
                     float u1, float v0, float v1, float z) {
  // The contract's u = 0.5 + (x n / z) / Fw solved for x (and v for y).
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
