// minmax_pcf's hierarchical count, step for step as the shaders walk
// (MinmaxCursor), so that a walk capped by a target counts what the shader
// counts, tests can hold the uncapped walk against brute force, and docs
// can quote its read counts.
#include "penumbra/reference/minmax_cursor.hpp"
#include "penumbra/reference/minmax_mip.hpp"

namespace penumbra::reference {

MipCount count_occluders(const MinMaxMip& mip, const TexelRect& window, float z_ref,
                         int max_steps) {
  MipCount result;
  const TexelRect clipped = clip(window, mip.width(0), mip.height(0));
  if (clipped.empty()) return result;
  MinmaxCursor cursor(clipped);
  for (; !cursor.done() && result.steps < max_steps; ++result.steps) {
    bool descend = false;
    // A root past the level's last node has an empty part and is skipped too.
    const TexelRect inside = intersect(cursor.texels(), clipped);
    if (!cursor.climbed()) ++result.visits;
    if (!cursor.climbed() && !inside.empty()) {
      ++result.reads;
      const MinMax values = mip.node(cursor.level(), cursor.x(), cursor.y());
      if (values.max < z_ref) {
        result.count += inside.count();
      } else {
        // min < z_ref <= max cannot hold at level 0, where min == max.
        descend = z_ref > values.min && cursor.level() > 0;
      }
    }
    if (descend) {
      cursor.descend();
    } else {
      cursor.next();
    }
  }
  result.truncated = !cursor.done();
  return result;
}

}  // namespace penumbra::reference
