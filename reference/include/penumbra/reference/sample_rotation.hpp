// The `rotation` key: where a variant's sample set lies at each pixel
// (docs/techniques.md, "Per-pixel rotation").
#pragma once

#include "penumbra/model/model.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {

// `disk` as the shader places it at the receiver's pixel: as baked, or with
// the `rotation` key turned (round sets) or shifted on the square's torus
// (square sets) by interleaved gradient noise. `ambiguous` is set where a
// shifted point lies too close to the torus's seam for float32 to say on
// which side it wraps.
Disk placed_disk(const Disk& disk, const VariantKeys& keys, const Query& q, bool& ambiguous);

}  // namespace penumbra::reference
