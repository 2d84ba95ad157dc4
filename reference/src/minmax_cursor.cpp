#include "penumbra/reference/minmax_cursor.hpp"

namespace penumbra::reference {

MinmaxCursor::MinmaxCursor(const TexelRect& window)
    : level_(start_level(window)), span_(1 << level_), start_(level_) {
  first_x_ = x_ = window.x0 >> level_;
  first_y_ = y_ = window.y0 >> level_;
}

TexelRect MinmaxCursor::texels() const {
  return {x_ * span_, y_ * span_, x_ * span_ + span_ - 1, y_ * span_ + span_ - 1};
}

void MinmaxCursor::descend() {
  steps_to_end_ += 4;
  x_ *= 2;
  y_ *= 2;
  --level_;
  span_ /= 2;
}

void MinmaxCursor::next() {
  const bool root = level_ >= start_;
  const int first_x = root ? first_x_ : x_ / 2 * 2;
  const int first_y = root ? first_y_ : y_ / 2 * 2;
  climbed_ = false;
  --steps_to_end_;
  if (x_ == first_x) {
    ++x_;
  } else if (y_ == first_y) {
    x_ = first_x;
    ++y_;
  } else if (root) {
    done_ = true;
  } else {
    x_ /= 2;
    y_ /= 2;
    ++level_;
    span_ *= 2;
    climbed_ = true;
  }
}

}  // namespace penumbra::reference
