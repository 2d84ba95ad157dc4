// The shaders' stack-free walk of the min-max hierarchy
// (shaderlib/common/minmax_traversal.glsl), step for step: the same start
// level, roots, child order and steps as its MinmaxCursor. Where a target
// caps a walk's steps (hlsl_dx9), a result depends on the steps taken, so
// the reference walks exactly as the shader does.
#pragma once

#include "penumbra/reference/minmax_mip.hpp"

namespace penumbra::reference {

class MinmaxCursor {
 public:
  // On the first of the 2 x 2 roots of start_level(window); `window` is
  // non-empty and inside the map.
  explicit MinmaxCursor(const TexelRect& window);

  int level() const { return level_; }
  int x() const { return x_; }
  int y() const { return y_; }
  // The node's map texels, not clipped to the map.
  TexelRect texels() const;
  // Risen to a parent whose subtree is done: this step moves past it and
  // stands on no node.
  bool climbed() const { return climbed_; }
  bool done() const { return done_; }

  // The steps the walk takes from here, this one included, if it descends
  // no further: 4 at the roots; a step takes one, a descent adds four (the
  // children, then the rise past them). A walk capped at n steps that
  // descends only while it then still ends within them (backprojection's
  // BACKPROJECTION_FINISH_COARSE) ends, and descends wherever the uncapped
  // walk would, if that takes at most n steps.
  int steps_to_end() const { return steps_to_end_; }

  // To the node's first child.
  void descend();
  // One step past the node's subtree: to its next sibling, or up to the
  // parent after the last sibling; done after the last root.
  void next();

 private:
  int x_ = 0, y_ = 0, level_ = 0, span_ = 1;
  int first_x_ = 0, first_y_ = 0, start_ = 0;
  int steps_to_end_ = 4;
  bool climbed_ = false;
  bool done_ = false;
};

}  // namespace penumbra::reference
