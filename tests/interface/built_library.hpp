// The default library (permutations/default.json) as the proofs read it:
// built with build_library into a temporary directory and read back with
// load_library, one variant and the targets a test proves at a time (ctest
// runs each test in a process of its own, so each builds only what it
// proves; a whole run of the binary builds each once and keeps it).
#pragma once

#include <string>
#include <vector>

#include "penumbra/library/library.hpp"
#include "proof.hpp"

namespace penumbra::testing {

// The library holding `name` alone, for those of its targets that are in
// `targets`, built on first use and removed at exit; the error names the
// variant or the build failure.
Result<const Library*> default_library_of(const std::string& name,
                                          const std::vector<Target>& targets);

// `prover` over every pass of the default variant `name` for each of
// `targets`: one error listing every pass that fails.
Status prove_default_variant(const std::string& name, Prover prover,
                             const std::vector<Target>& targets);

}  // namespace penumbra::testing
