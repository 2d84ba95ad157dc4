// variant.glsl: the generated header every shader includes first. It holds
// the target's defines and the variant's technique, sample counts, Poisson
// disks and blur weights as constant arrays.
#pragma once

#include <string>

#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/model.hpp"

namespace penumbra {

// `variant` may be null for shaders shared by every variant whose map is in
// `shared_encoding`; a variant's own shaders take its map_encoding key.
// PENUMBRA_MAP_ENCODING is defined for every encoding but linear.
std::string variant_header(const Variant* variant, Target target,
                           MapEncoding shared_encoding = MapEncoding::linear);

// A float formatted so that reading it back as float32 gives the same bits.
std::string glsl_float(float value);

}  // namespace penumbra
