// Library entries for verify's device-free tests: a variant with only what
// the plan reads (its name, technique, keys and targets), and a library of
// them.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "penumbra/library/library.hpp"

namespace penumbra::testing {

inline LibraryVariant planned_variant(std::string name, Technique technique,
                                      std::vector<Target> targets, VariantKeys keys = {}) {
  LibraryVariant entry;
  entry.variant.name = std::move(name);
  entry.variant.technique = technique;
  entry.variant.keys = std::move(keys);
  entry.variant.targets = std::move(targets);
  return entry;
}

// Two map encodings, a min-max technique, and variants on different targets.
inline Library planned_library() {
  Library lib;
  lib.root = "lib";
  lib.variants.push_back(
      planned_variant("hard", Technique::hard, {Target::spirv, Target::glsl450}));
  lib.variants.push_back(planned_variant("pcss_perspective", Technique::pcss, {Target::spirv},
                                         VariantKeys{.map_encoding = "perspective"}));
  lib.variants.push_back(
      planned_variant("minmax_pcf", Technique::minmax_pcf, {Target::spirv, Target::glsl450}));
  lib.variants.push_back(planned_variant("minmax_dx9", Technique::minmax_pcf, {Target::hlsl_dx9}));
  return lib;
}

}  // namespace penumbra::testing
