// The runtime tests' programs: SPIR-V compiled from shaders/ at build time,
// with reflection records written by hand to match the GLSL.
#pragma once

#include <memory>

#include "penumbra/runtime/engine.hpp"

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

PassProgram depth_program();            // depth.vert + depth.frag
PassProgram compare_program();          // fullscreen.vert + compare.frag: shadow_cmp at (u, v, z_r)
PassProgram point_program();            // fullscreen.vert + point.frag: shadow_depth, no shadow_cmp
PassProgram point_with_cmp_program();   // the same, with shadow_cmp declared
PassProgram unknown_sampler_program();  // fullscreen.vert + unknown_sampler.frag: "shadow_mapp"

// An engine on the default device (lavapipe); fails the test if none.
std::unique_ptr<Engine> make_engine(bool validation = false);

// A receivers image of one row holding the (u, v, z_r) points in order.
FloatImage receivers_row(const std::vector<std::array<float, 3>>& points);

}  // namespace penumbra::test
