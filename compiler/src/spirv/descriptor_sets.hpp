// Moving a module's descriptors to another descriptor set, as a binding map
// would have placed them.
#pragma once

#include <cstdint>
#include <vector>

namespace penumbra {

// Every DescriptorSet decoration of `spirv` made `set`; bindings unchanged.
void move_to_descriptor_set(std::vector<std::uint32_t>& spirv, std::uint32_t set);

}  // namespace penumbra
