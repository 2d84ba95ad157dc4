// What the tests check in a front end's SPIR-V, read independently of the
// code under test: validity (spirv-val), the module's variables with
// their names and interface decorations, its built-ins and precisions,
// straight from its words.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace penumbra::testing {

struct SpirvVariable {
  std::string name;  // OpName; empty when none
  std::uint32_t storage_class = 0;
  std::optional<std::uint32_t> set, binding, location;
  bool builtin = false;  // decorated BuiltIn, or a block of BuiltIn members
};

inline constexpr std::uint32_t kStorageInput = 1;
inline constexpr std::uint32_t kStorageOutput = 3;
inline constexpr std::uint32_t kStorageUniformConstant = 0;
inline constexpr std::uint32_t kStorageUniform = 2;
inline constexpr std::uint32_t kBuiltInPosition = 0;
inline constexpr std::uint32_t kBuiltInFragDepth = 22;

// spirv-val's messages for Vulkan 1.0; empty when the module is valid.
std::string vulkan_validation_errors(std::span<const std::uint32_t> spirv);

// Every OpVariable of the module, in order.
std::vector<SpirvVariable> spirv_variables(std::span<const std::uint32_t> spirv);

// Every BuiltIn decorating a variable or a block member.
std::set<std::uint32_t> spirv_builtins(std::span<const std::uint32_t> spirv);

// Whether anything is decorated RelaxedPrecision (GLSL mediump or lowp).
bool has_relaxed_precision(std::span<const std::uint32_t> spirv);

}  // namespace penumbra::testing
