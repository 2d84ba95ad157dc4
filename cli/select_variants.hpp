// `penumbra build --variant NAME --target NAME`: which of a manifest's
// variants and targets to build.
#pragma once

#include <string>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::cli {

// Keeps the variants named in `names` (all when empty) and, of their targets,
// those in `targets` (all when empty); a variant left without targets is
// dropped. Errors (bad_input) name the argument: an unknown variant (with the
// closest names of the manifest `manifest`), an unknown target (with the
// allowed ones), or a selection that leaves nothing to build.
Result<std::vector<Variant>> select_variants(std::vector<Variant> variants,
                                             const std::vector<std::string>& names,
                                             const std::vector<std::string>& targets,
                                             const std::string& manifest);

}  // namespace penumbra::cli
