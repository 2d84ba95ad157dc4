// variant.glsl: the generated header every shader includes first. It holds
// the target's defines and the variant's technique, sample counts, Poisson
// disks and blur weights as constant arrays.
#pragma once

#include <string>

#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/model.hpp"

namespace penumbra {

// `variant` may be null for shaders shared by variants; `encoding` is the
// job's map encoding (job_encoding()), for which PENUMBRA_MAP_ENCODING is
// defined unless it is linear.
std::string variant_header(const Variant* variant, Target target,
                           MapEncoding encoding = MapEncoding::linear);

// A float formatted so that reading it back as float32 gives the same bits.
std::string glsl_float(float value);

}  // namespace penumbra
