// The SPIR-V modules a build made last, by what they were made from: a
// pass's targets whose preprocessed text is the same (the three GLSL
// targets, Direct3D 10 and 11) compile, validate and optimize it once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/compiler/stage.hpp"

namespace penumbra {

// What the module stages (compile, validate, optimize) read of a job, as a
// key: its stage, form, source and preprocessed text, and the variant whose
// baked constants they name. Not the target: the banner comes after.
std::string module_key(const ShaderJob& job);

// The `capacity` modules added last, found by key; safe from any thread. A
// build's jobs that share a module are a few jobs apart in plan order (one
// variant's targets follow each other), so a short memory finds them.
class ModuleMemo {
 public:
  explicit ModuleMemo(std::size_t capacity) : capacity_(capacity) {}
  std::optional<std::vector<std::uint32_t>> find(const std::string& key) const;
  void add(const std::string& key, const std::vector<std::uint32_t>& spirv);

 private:
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::deque<std::pair<std::string, std::vector<std::uint32_t>>> modules_;  // oldest first
};

}  // namespace penumbra
