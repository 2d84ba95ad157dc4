// A 5x7 pixel font, with two rows for descenders, for the labels of the
// report's PNGs (the cost chart, the contact sheet): lower-case letters,
// digits and "._-/()%,:+=<>"; upper case is drawn as lower case, anything
// else as a space.
#pragma once

#include <string_view>

#include "png_file.hpp"

namespace penumbra::report {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 9;   // 7 above the baseline, 2 below
inline constexpr int kGlyphAdvance = 6;  // one blank column between letters

// Width of `text` in pixels at `scale` (each font pixel scale x scale).
int text_width(std::string_view text, int scale = 1);

// Draws `text` with its top-left corner at (x, y); pixels outside the
// picture are skipped.
void draw_text(Picture& picture, int x, int y, std::string_view text, Rgb colour, int scale = 1);

// `picture` with `text` in white on a dark band across its top (the
// contact sheet's thumbnails, each named by its variant).
Picture labelled(Picture picture, std::string_view text);

}  // namespace penumbra::report
