#include "penumbra/compiler/disk.hpp"

namespace penumbra {

// NVIDIA's "Percentage-Closer Soft Shadows" whitepaper (Fernando 2005), its
// poissonDisk[16] in order. Kept point for point although 8 of the points lie
// outside the unit disk (the 8th at radius 1.23): shaders built with this set
// must match the whitepaper's.
Disk whitepaper16() {
  Disk disk;
  disk.name = "whitepaper16";
  disk.method = "whitepaper";
  disk.seed = 0;
  disk.points = {
      {-0.94201624f, -0.39906216f}, {0.94558609f, -0.76890725f},  {-0.094184101f, -0.92938870f},
      {0.34495938f, 0.29387760f},   {-0.91588581f, 0.45771432f},  {-0.81544232f, -0.87912464f},
      {-0.38277543f, 0.27676845f},  {0.97484398f, 0.75648379f},   {0.44323325f, -0.97511554f},
      {0.53742981f, -0.47373420f},  {-0.26496911f, -0.41893023f}, {0.79197514f, 0.19090188f},
      {-0.24188840f, 0.99706507f},  {-0.81409955f, 0.91437590f},  {0.19984126f, 0.78641367f},
      {0.14383161f, -0.14100790f},
  };
  disk.normalized_min_distance = normalized_min_distance(disk.points);
  return disk;
}

}  // namespace penumbra
