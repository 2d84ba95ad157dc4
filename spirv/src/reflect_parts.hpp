// The parts of reflect(): each reads one kind of record from a SPIRV-Cross
// compiler holding the module.
#pragma once

#include <cstdint>
#include <span>
#include <spirv_cross/spirv_cross.hpp>

#include "penumbra/spirv/reflection.hpp"

namespace penumbra::detail {

// A uniform block with its struct members flattened to leaves.
UniformBlock reflect_block(const spirv_cross::Compiler& compiler,
                           const spirv_cross::Resource& resource);

// Combined image samplers, separate images and separate samplers, each
// ordered by set, then binding. Pairs samplers with images by name and marks
// the samplers used with depth images or depth comparisons in `spirv`, the
// module (this analysis changes `compiler`'s module, so it runs after every
// other query).
void reflect_images(spirv_cross::Compiler& compiler, const spirv_cross::ShaderResources& resources,
                    std::span<const std::uint32_t> spirv, ShaderInterface& iface);

}  // namespace penumbra::detail
