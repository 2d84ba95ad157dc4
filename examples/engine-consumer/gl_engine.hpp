// What both OpenGL programs (engine_consumer_gl, engine_consumer_gl_lights)
// do as an engine of their own would: an OpenGL 3.3 core context, programs,
// vertex arrays, the function form's inputs bound from its reflection, and
// the PNG. Needs a GL context current for all but create_context() and
// write_png().
#pragma once

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <png.h>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine_shadows/shaders.hpp"
#include "scene.hpp"

namespace gl_engine {

using Mat4 = std::array<float, 16>;  // column-major, as glUniformMatrix4fv takes it

// The glsl330 function form of PCSS with 16 blocker-search and 16 filter
// samples on the NVIDIA PCSS whitepaper's disk, and `keys`' map encoding
// and layout, from the shaders compiled into the program, with its
// reflection; null with `log` set where shadows.json does not build it or it
// needs GLSL extensions, which these engines do not enable.
const penumbra::shaders::Function* pcss_function(const penumbra::VariantKeys& keys,
                                                 nlohmann::json& reflection, std::string& log);

// The light's view-projection: x and y scaled by 2n / Fw, w = z, and z
// mapped to [-w, w] from n to f, so that the depth buffer stores
// f (z - n) / (z (f - n)): the `perspective` map encoding.
Mat4 light_matrix();

// Draws the ground (the plane z = kGroundZ within the picture) with
// `program`, its `camera` uniform camera_matrix(), into the bound
// framebuffer's kImageSize x kImageSize pixels.
void draw_ground(GLuint program);

// An OpenGL 3.3 core context with nothing to draw on but its own
// framebuffers: Mesa's surfaceless platform, else the default display.
bool create_context();

// A linked program of `vertex` and `fragment` (attribute 0: `position`),
// or 0 with `log` saying why.
GLuint link(const std::string& vertex, const std::string& fragment, std::string& log);

// A vertex array of `triangles` at attribute 0.
GLuint vertex_array(const std::vector<scene::Vec3>& triangles);

// A sampler object in a reflected sampler state (docs/shader-interface.md).
GLuint sampler_object(const nlohmann::json& state);

// Binds the function form's textures and constants in `program` as its
// reflection names them, ShadowParams' members from `values` by name: the
// map on consecutive units from 0 (a 2D array where the reflection's type
// says so), each through a sampler object in its reflected state;
// ShadowParams as loose uniforms (glsl330 has them; one the function does
// not read may be gone), or as a block at binding 0.
bool bind_function_inputs(GLuint program, const nlohmann::json& reflection, GLuint map,
                          const nlohmann::json& values, std::string& log);

// A width x height GL_DEPTH_COMPONENT32F texture, one level, attached to a
// new framebuffer left bound (no colour buffer): the engine's shadow map.
// With `layers`, a 2D array of that many, layer 0 attached.
GLuint depth_target(int width, int height, int layers = 0);

// A kImageSize x kImageSize RGBA8 texture attached to a new framebuffer
// left bound: the picture. Created before the function's textures are
// bound, since creating a texture binds it to the active unit.
void picture_target();

// Channel `channel` of the bound framebuffer's kImageSize x kImageSize
// pixels, row 0 first; empty with `log` set on an OpenGL error.
std::vector<png_byte> read_channel(int channel, std::string& log);

// `grey` (kImageSize x kImageSize, row 0 first) as an 8-bit greyscale PNG.
bool write_png(const std::string& path, const std::vector<png_byte>& grey);

}  // namespace gl_engine
