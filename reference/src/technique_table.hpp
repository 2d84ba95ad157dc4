// Each technique's CPU reference in one row: what its variant must carry,
// how one receiver is evaluated, whether that reads the min-max mip, the
// tolerance a GPU result is held to (docs/verification.md), and what its
// screen passes after the query do. A new technique
// adds a row here, beside its TechniqueDescription (model/) and its shader.
#pragma once

#include "penumbra/reference/techniques.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::reference::detail {

// One receiver's inputs. `mip` is null unless the row reads_mip.
struct ReceiverInputs {
  const Variant& variant;
  const ShadowMapView& map;
  const MinMaxMip* mip;
  const LightParams& light;
  const Query& query;
  double z_ref;  // query.z - bias: what comparisons use
  const SamplingPrecision& precision;
  const ShaderLimits& limits;
};

struct TechniqueReference {
  Technique technique;
  bool reads_mip;                                 // evaluate() needs the min-max mip
  Status (*check)(const Variant& variant);        // check_variant()
  Sample (*evaluate)(const ReceiverInputs&);      // evaluate()
  double (*tolerance)(const SamplingPrecision&);  // tolerance()
  // What the technique's screen passes after the query do to its image
  // (screen_visibility()); none where the query's image is the result.
  FloatImage (*screen_filter)(const Variant&, const FloatImage& visibility,
                              const FloatImage& receivers) = nullptr;
};

const TechniqueReference& reference_for(Technique technique);

}  // namespace penumbra::reference::detail
