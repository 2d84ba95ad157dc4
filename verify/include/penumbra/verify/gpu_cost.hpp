// What a variant costs on the GPU (docs/performance.md): its SPIR-V passes
// on the Vulkan engine, each timed with timestamp queries around its draws,
// the median of a number of runs after an untimed one (a driver may compile
// a pipeline lazily on its first use). The same method serves the GPU
// benchmark (penumbra_bench_gpu) and the report's cost chart.
#pragma once

#include <string>

#include "penumbra/verify/pictures.hpp"

namespace penumbra {

struct GpuCostOptions {
  int runs = 21;  // timed runs of each pass after an untimed one; the median is reported
};

// One variant's passes on one scene.
struct GpuCost {
  std::string variant;
  Technique technique = Technique::hard;
  double depth_ms = 0.0;               // the depth pass's median GPU time
  double mip_ms = 0.0;                 // the min-max mip build's (minmax techniques; else 0)
  double query_ms = 0.0;               // the query pass's (screen_blur: its four passes summed)
  double texel_reads_per_pixel = 0.0;  // the query's .y, the mean over every screen pixel
  // The untimed run's images: what the variant shows (screen_blur: the
  // blurred factor) and the query's texel reads per pixel.
  FloatImage visibility;
  FloatImage texel_reads;

  double total_ms() const { return depth_ms + mip_ms + query_ms; }
};

// The device's texel rate on the scene: a fetch-only query shader that reads
// the map through shadow_cmp, with the sampler state a variant's query pass
// declares, `fetches` times per pixel (an 8-texel-wide square of bilinear
// comparisons around the receiver's uv), and does nothing else.
struct FetchCeiling {
  std::string sampler_of;  // the variant whose shadow_cmp sampler state it uses
  int fetches = 0;
  double query_ms = 0.0;               // median GPU time
  double texel_reads_per_pixel = 0.0;  // its .y: 4 per comparison, as the variants count
};

// Texels read per second, in billions: `pixels` times `reads_per_pixel` in `ms`.
double gigatexels_per_second(double pixels, double reads_per_pixel, double ms);

// `entry`'s spirv passes on `scene`: depth, min-max mip when its technique
// reads one, and query. Errors: bad_input when the library has no spirv for
// it; device when the device writes no timestamps or a pass fails.
Result<GpuCost> measure_gpu_cost(const Library& library, Engine& engine,
                                 const LibraryVariant& entry, const PictureScene& scene,
                                 const GpuCostOptions& options);

// The fetch-only ceiling with `like`'s sampler state, on the map `like`'s
// depth pass draws of `scene`. Errors: bad_input when `like`'s spirv query
// pass reads no shadow_cmp; compile when the shader fails; device as above.
Result<FetchCeiling> measure_fetch_ceiling(const Library& library, Engine& engine,
                                           const LibraryVariant& like, const PictureScene& scene,
                                           int fetches, const GpuCostOptions& options);

// Whether `entry`'s spirv query pass samples the map through shadow_cmp
// (a variant measure_fetch_ceiling can take its sampler state from).
bool reads_comparison_sampler(const LibraryVariant& entry);

}  // namespace penumbra
