// Each technique's CPU reference in one row: what its variant must carry,
// how one receiver is evaluated, whether that reads the min-max mip, and the
// tolerance a GPU result is held to (docs/verification.md). A new technique
// adds a row here, beside its TechniqueDescription (model/) and its shader.
#pragma once

#include "penumbra/reference/techniques.hpp"

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
};

const TechniqueReference& reference_for(Technique technique);

}  // namespace penumbra::reference::detail
