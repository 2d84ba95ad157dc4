// The runtime tests' programs: SPIR-V compiled from shaders/ at build time,
// reflected by reflect() as the driver sees it, each with the spirv
// reflection record of the shaderlib pass that declares the same resources
// (compile_pass), which the engine binds by.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "penumbra/compiler/build.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra::test {

// Light and map parameters of the tests. depth_scale is a power of two.
struct TestLight {
  float light_size = 0.5f;      // L
  float frustum_width = 3.75f;  // Fw
  float near_plane = 9.5f;      // n
  float bias = 0.0f;
  float depth_scale = 1.0f / 32.0f;
};

// Every ShadowParams member, for a map of map_w x map_h and an output of screen_w x screen_h.
ParamBlock make_params(const TestLight& light, int map_w, int map_h, int screen_w, int screen_h);

// The words of shaders/<name> compiled at build time (<name>.spv); fails the test if missing.
std::vector<std::uint32_t> read_spirv(const std::string& name);

// The default variant `variant`'s `pass` compiled for `target`
// (compile_pass, once per process); null, with a test failure, if it fails.
const CompiledPass* compiled_pass(const std::string& variant, PassKind pass, Target target);

// Its reflection record (empty, with a test failure, if it fails).
PassReflection pass_reflection(const std::string& variant, PassKind pass,
                               Target target = Target::spirv);

// depth.vert + depth.frag; "depth_flip_y.vert" is depth.vert negating clip y.
PassProgram depth_program(const std::string& vert_name = "depth.vert");
PassProgram compare_program();         // fullscreen.vert + compare.frag: shadow_cmp at (u, v, z_r)
PassProgram point_program();           // fullscreen.vert + point.frag: shadow_depth, no shadow_cmp
PassProgram point_with_cmp_program();  // the same, with shadow_cmp declared
// fullscreen.vert + unknown_sampler.frag: point.frag's resources and a
// sampler "shadow_mapp" at binding 7, which no reflection has.
PassProgram unknown_sampler_program();
// The min-max build passes (minmax_init.frag reads shadow_depth, minmax_reduce.frag
// minmax_source), and a query returning shadow_minmax's (min, max) at (u, v, lod).
// "minmax_init_swapped.frag" is minmax_init.frag writing (max, min): a wrong mip.
PassProgram minmax_init_program(const std::string& frag_name = "minmax_init.frag");
PassProgram minmax_reduce_program();
PassProgram minmax_probe_program();

// An engine on the default device (lavapipe); fails the test if none. The
// validation layers are on unless asked otherwise, and a message of theirs
// fails the test.
std::unique_ptr<Engine> make_engine(bool validation = true);

// Two triangles covering [u0, u1] x [v0, v1] of the map at light-view depth z.
void add_caster_quad(std::vector<std::array<float, 3>>& triangles, const TestLight& light, float u0,
                     float u1, float v0, float v1, float z);

// A receivers image of one row holding the (u, v, z_r) points in order.
FloatImage receivers_row(const std::vector<std::array<float, 3>>& points);

// A fixture for binding errors: an engine and a 2 x 2 shadow map to query.
class EngineWithMapTest : public ::testing::Test {
 protected:
  void SetUp() override;

  // Runs `program` over a 2 x 2 receivers image; expects it to fail and
  // returns the error (an empty Error, with a test failure, if it ran).
  Error failed_query(const PassProgram& program, const ParamBlock& params);

  std::unique_ptr<Engine> engine_;
  std::shared_ptr<ShadowMap> map_;
};

}  // namespace penumbra::test
