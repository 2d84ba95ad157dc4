// The texture reads the techniques are built from, as docs/techniques.md defines
// them (section 1). Coordinates are shadow-map uv; depths are linear z.
#pragma once

#include <array>

#include "penumbra/reference/shadow_map.hpp"

namespace penumbra::reference {

// A comparison is lit when the reference depth (z_r - bias) is not behind the
// stored depth (LESS_EQUAL); otherwise the texel occludes.
inline bool lit(double z_ref, double depth) {
  return z_ref <= depth;
}

// The comparison reference z_r - bias as the GPU's float32 arithmetic forms
// it (shadow_reference() scales it by a power of two, which is exact), for
// the techniques whose comparisons must agree with the GPU bit for bit.
inline float float_reference(double z_receiver, double bias) {
  return float(z_receiver) - float(bias);
}

struct Texel {
  int i = 0;
  int j = 0;
};

// The texels a point sample at (u, v) may read on a GPU whose texel
// coordinates can be off by up to `window` texels (0 <= window < 1): the
// nearest texel first, then the others across any texel boundary within
// `window` of (u W, v H). One, two or four texels.
struct TexelCandidates {
  std::array<Texel, 4> texels;
  int count = 0;
};
TexelCandidates candidate_texels(const ShadowMapView& map, double u, double v, double window);

// Whether `value(texel)` differs between the candidates, i.e. whether a point
// sample's result depends on which of them the GPU reads.
template <typename F>
bool varies(const TexelCandidates& candidates, F value) {
  const auto first = value(candidates.texels[0]);
  for (int k = 1; k < candidates.count; ++k) {
    if (value(candidates.texels[k]) != first) return true;
  }
  return false;
}

// Bilinear comparison at (u, v): the four texels around (u W - 0.5, v H - 0.5),
// each compared against z_ref, blended with bilinear weights.
double bilinear_compare(const ShadowMapView& map, double u, double v, double z_ref);

}  // namespace penumbra::reference
