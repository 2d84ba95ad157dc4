// The proofs must be able to fail: one reflection entry of a variant that
// reads every kind of resource (pcss: a comparison sampler, point reads,
// receivers, ShadowParams) changed in memory, and the prover's verdict.
#pragma once

#include <functional>
#include <string>

#include "proof.hpp"

namespace penumbra::testing {

// The default variant the corruption tests change.
inline constexpr const char* kCorruptedVariant = "pcss_b16_p16_poisson";

// `prover` on `pass` of kCorruptedVariant for `target` after `corrupt` has
// changed a copy of its reflection; the error (or "" when the proof passed).
std::string prove_corrupted(Prover prover, PassKind pass, Target target,
                            const std::function<void(PassReflection&)>& corrupt);

}  // namespace penumbra::testing
