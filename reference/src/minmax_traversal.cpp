// minmax_pcf's hierarchical count, node for node in the shaders' order, so
// that tests can hold it against the brute-force count and docs can quote its
// read counts. The CPU keeps an explicit stack, children pushed in reverse so
// that they pop in the design's order; the GPU has no stack (ps_3_0 cannot
// index temporaries) and steps a cursor from node to node instead
// (shaderlib/common/minmax_traversal.glsl), visiting the same nodes.
#include <vector>

#include "penumbra/reference/minmax_mip.hpp"

namespace penumbra::reference {
namespace {

struct Node {
  int level;
  int i;
  int j;
};

}  // namespace

MipCount count_occluders(const MinMaxMip& mip, const TexelRect& window, float z_ref) {
  MipCount result;
  const TexelRect clipped = clip(window, mip.width(0), mip.height(0));
  if (clipped.empty()) return result;
  const int start = start_level(clipped);
  const int i0 = clipped.x0 >> start, j0 = clipped.y0 >> start;
  std::vector<Node> stack = {
      {start, i0 + 1, j0 + 1}, {start, i0, j0 + 1}, {start, i0 + 1, j0}, {start, i0, j0}};
  while (!stack.empty()) {
    const Node node = stack.back();
    stack.pop_back();
    ++result.visits;
    // A root past the level's last node has an empty extent and is skipped too.
    const TexelRect inside = intersect(mip.extent(node.level, node.i, node.j), clipped);
    if (inside.empty()) continue;
    ++result.reads;
    const MinMax values = mip.node(node.level, node.i, node.j);
    if (z_ref <= values.min) continue;
    if (values.max < z_ref) {
      result.count += inside.count();
      continue;
    }
    // min < z_ref <= max cannot hold at level 0, where min == max.
    const int level = node.level - 1, i = 2 * node.i, j = 2 * node.j;
    stack.insert(stack.end(),
                 {{level, i + 1, j + 1}, {level, i, j + 1}, {level, i + 1, j}, {level, i, j}});
  }
  return result;
}

}  // namespace penumbra::reference
