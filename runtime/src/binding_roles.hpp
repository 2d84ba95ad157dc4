// What each reflected resource of one stage is in the shader interface: its
// interface name, its role and its descriptor type (docs/runtime.md,
// "Binding by reflection").
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "binding_plan.hpp"

namespace penumbra::detail {

struct ResolvedResource {
  std::string name;                 // as reflected, e.g. "_shadow_cmp_sampler"
  std::string_view interface_name;  // what PassResources::available() lists, e.g. "shadow_cmp"
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  BindingRole role = BindingRole::params;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  const UniformBlock* block = nullptr;  // for a uniform block
};

// "a, b, c": the names in order, for messages.
std::string joined(std::span<const std::string_view> names);

// True when either stage declares the image `image_name` (as a sampler2D or
// a separate image).
bool declares_image(const PassProgram& program, std::string_view image_name);

// True when either stage declares shadow_cmp (as a sampler2DShadow or a
// separate image): then shadow_depth reads the map's depth image, else the
// R32F image (the Direct3D 9 style, comparing in the shader).
bool declares_comparison(const PassProgram& program);

// Every resource of `iface`: blocks, combined image samplers, separate
// images, separate samplers. Errors (bad_input, where = `pass`) name a
// resource outside the interface or of the wrong kind.
Result<std::vector<ResolvedResource>> resolve_stage(const ShaderInterface& iface,
                                                    bool has_comparison, std::string_view pass);

}  // namespace penumbra::detail
