// The three kinds of pass the engine draws (docs/shader-interface.md): what
// each binds, what it writes and the name its errors carry.
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "gl_api.hpp"

namespace penumbra::gl {

// An image of the shader interface: its sampler type and the binding
// docs/shader-interface.md gives it (set 0).
struct ImageSlot {
  std::string_view name;
  GLenum type;
  std::string_view type_name;
  GLint binding;
};

inline constexpr std::array kImageSlots = {
    ImageSlot{"shadow_depth", GL_SAMPLER_2D, "sampler2D", 1},
    ImageSlot{"shadow_cmp", GL_SAMPLER_2D_SHADOW, "sampler2DShadow", 2},
    ImageSlot{"receivers", GL_SAMPLER_2D, "sampler2D", 3},
    ImageSlot{"shadow_minmax", GL_SAMPLER_2D, "sampler2D", 4},
    ImageSlot{"minmax_source", GL_SAMPLER_2D, "sampler2D", 5},
};

// The interface slot named `name`, or null.
inline const ImageSlot* find_image_slot(std::string_view name) {
  for (const ImageSlot& slot : kImageSlots) {
    if (slot.name == name) return &slot;
  }
  return nullptr;
}

struct PassRole {
  std::string_view where;   // Error::where of everything the pass reports
  std::string_view output;  // the fragment output at colour 0
  // The images the pass binds; the first is its input and must be active.
  std::span<const std::string_view> images;
  std::string_view input_use;  // why the first image is needed
};

inline constexpr std::array<std::string_view, 4> kQueryImages = {"receivers", "shadow_depth",
                                                                 "shadow_cmp", "shadow_minmax"};
inline constexpr std::array<std::string_view, 1> kMinmaxInitImages = {"shadow_depth"};
inline constexpr std::array<std::string_view, 1> kMinmaxReduceImages = {"minmax_source"};

inline constexpr PassRole kQueryPass{"query pass", "visibility", kQueryImages,
                                     "the query pass reads each pixel's (u, v, z_r) through it"};
inline constexpr PassRole kMinmaxInitPass{
    "minmax_init pass", "minmax", kMinmaxInitImages,
    "the minmax_init pass reduces the shadow map it reads through it"};
inline constexpr PassRole kMinmaxReducePass{
    "minmax_reduce pass", "minmax", kMinmaxReduceImages,
    "the minmax_reduce pass reduces the min-max level it reads through it"};

}  // namespace penumbra::gl
