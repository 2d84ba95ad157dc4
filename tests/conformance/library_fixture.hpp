// One variant of permutations/default.json, built into a temporary library
// (ctest runs every test in its own process, so each builds only its own
// variant), with a Vulkan engine to run it.
#pragma once

#include <string>
#include <vector>

#include "penumbra/compiler/library.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra::testing {

// Variant names of permutations/default.json (test parameters).
std::vector<std::string> default_variant_names();

struct VariantLibrary {
  Library library;                 // holds exactly the one variant
  std::unique_ptr<Engine> engine;  // null unless requested
  ~VariantLibrary();               // removes the temporary library
};

// Builds `name` for all its targets; fails the calling test (and returns
// null) on error.
std::unique_ptr<VariantLibrary> build_default_variant(const std::string& name, bool with_engine);

// A test name made of letters, digits and underscores.
std::string test_name(std::string name);

}  // namespace penumbra::testing
