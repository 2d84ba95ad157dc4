#include "corrupted_reflection.hpp"

#include <gtest/gtest.h>

#include "built_library.hpp"

namespace penumbra::testing {

std::string prove_corrupted(Prover prover, PassKind pass, Target target,
                            const std::function<void(PassReflection&)>& corrupt) {
  auto library = default_library_of(kCorruptedVariant, {target});
  if (!library) return "no library: " + library.error().to_string();
  const LibraryVariant* found = (*library)->find(kCorruptedVariant);
  if (found == nullptr) return "no variant";
  LibraryVariant variant = *found;
  // The unchanged reflection is proved first: the corruption is what fails.
  if (auto clean = prover(**library, variant, pass, target); !clean) {
    ADD_FAILURE() << "the uncorrupted reflection fails: " << clean.error().to_string();
  }
  corrupt(variant.reflection.at(pass).at(target));
  const Status proved = prover(**library, variant, pass, target);
  return proved ? "" : proved.error().to_string();
}

}  // namespace penumbra::testing
