// FloatImage: a row-major float image, row j = 0 first (as in PFM files);
// or a 2D array texture's layers, stacked one after another.
#pragma once

#include <cstddef>
#include <cstring>
#include <vector>

namespace penumbra {

struct FloatImage {
  int width = 0;
  int height = 0;
  int channels = 1;         // 1 (Pf) or 3 (PF); 4 only in memory (GPU upload)
  std::vector<float> data;  // width * height * channels, row j = 0 first
  // 0: one 2D image. n >= 1: the n layers of a 2D array texture, each
  // height / n rows, layer k at rows [k * height / n, (k + 1) * height / n)
  // (a texture array's own order in memory).
  int layers = 0;

  FloatImage() = default;
  FloatImage(int w, int h, int c, float fill = 0.0f)
      : width(w), height(h), channels(c), data(static_cast<std::size_t>(w) * h * c, fill) {}

  float& at(int i, int j, int c = 0) { return data[index(i, j, c)]; }
  float at(int i, int j, int c = 0) const { return data[index(i, j, c)]; }
  std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }
  // The height of one layer: the image's, where it has no layers.
  int layer_height() const { return layers > 0 ? height / layers : height; }

 private:
  std::size_t index(int i, int j, int c) const {
    return (static_cast<std::size_t>(j) * width + i) * channels + c;
  }
};

// Whether `a` and `b` hold the same values byte for byte, their sizes and
// channels too: a NaN equals itself, -0 differs from 0.
inline bool same_bytes(const FloatImage& a, const FloatImage& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         a.layers == b.layers &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

}  // namespace penumbra
