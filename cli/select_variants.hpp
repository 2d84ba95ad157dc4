// `penumbra build --variant NAME --target NAME --form NAME`: which of a
// manifest's variants, targets and forms to build.
#pragma once

#include <string>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::cli {

// The arguments that narrow a build; each keeps all when empty.
struct Selection {
  std::vector<std::string> variants = {};  // --variant NAME
  std::vector<std::string> targets = {};   // --target NAME
  std::vector<std::string> forms = {};     // --form NAME
};

// Keeps the variants `selection` names and, of their targets and forms,
// those it names; a variant left without targets or forms is dropped.
// Errors (bad_input) name the argument: an unknown variant (with the closest
// names of the manifest `manifest`), an unknown target or form (with the
// allowed ones), or a selection that leaves nothing to build.
Result<std::vector<Variant>> select_variants(std::vector<Variant> variants,
                                             const Selection& selection,
                                             const std::string& manifest);

}  // namespace penumbra::cli
