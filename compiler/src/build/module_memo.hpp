// The SPIR-V modules a build made last, by what they were made from: a
// pass's targets whose preprocessed text is the same (the three GLSL
// targets, Direct3D 10 and 11) compile, validate, optimize and reflect it
// once.
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

// A module and its interface, as the module stages leave them.
struct Module {
  std::vector<std::uint32_t> spirv;
  ShaderInterface interface;
};

// What the module stages (compile, validate, optimize, interface) read of a job, as a
// key: its stage, form, source and preprocessed text, and the variant whose
// baked constants they name. Not the target: the banner comes after.
std::string module_key(const ShaderJob& job);

// The `capacity` modules added last, found by key; safe from any thread. A
// build's jobs that share a module are a few jobs apart in plan order (one
// variant's targets follow each other), so a short memory finds them.
class ModuleMemo {
 public:
  explicit ModuleMemo(std::size_t capacity) : capacity_(capacity) {}
  std::optional<Module> find(const std::string& key) const;
  void add(const std::string& key, Module module);

 private:
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::deque<std::pair<std::string, Module>> modules_;  // oldest first
};

}  // namespace penumbra
