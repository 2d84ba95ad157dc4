// A line-by-line transliteration of the NVIDIA PCSS whitepaper's "PCSS Shader
// Code".
// Names, constants and statement order are the whitepaper's; only the HLSL
// texture calls are emulated (below), in double precision. Deliberately no
// code is shared with techniques.cpp, so that the two readings check each
// other.
#include "penumbra/reference/whitepaper_pcss.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::reference {
namespace {

// #define BLOCKER_SEARCH_NUM_SAMPLES 16
constexpr int BLOCKER_SEARCH_NUM_SAMPLES = 16;
// #define PCF_NUM_SAMPLES 16
constexpr int PCF_NUM_SAMPLES = 16;
// #define NEAR_PLANE 9.5
constexpr double NEAR_PLANE = 9.5;
// #define LIGHT_WORLD_SIZE .5
constexpr double LIGHT_WORLD_SIZE = .5;
// #define LIGHT_FRUSTUM_WIDTH 3.75
constexpr double LIGHT_FRUSTUM_WIDTH = 3.75;
// #define LIGHT_SIZE_UV (LIGHT_WORLD_SIZE / LIGHT_FRUSTUM_WIDTH)
constexpr double LIGHT_SIZE_UV = (LIGHT_WORLD_SIZE / LIGHT_FRUSTUM_WIDTH);

// cbuffer POISSON_DISKS { float2 poissonDisk[16] = { ... }; };
constexpr std::array<Point2, 16> poissonDisk = {{
    {-0.94201624f, -0.39906216f},
    {0.94558609f, -0.76890725f},
    {-0.094184101f, -0.92938870f},
    {0.34495938f, 0.29387760f},
    {-0.91588581f, 0.45771432f},
    {-0.81544232f, -0.87912464f},
    {-0.38277543f, 0.27676845f},
    {0.97484398f, 0.75648379f},
    {0.44323325f, -0.97511554f},
    {0.53742981f, -0.47373420f},
    {-0.26496911f, -0.41893023f},
    {0.79197514f, 0.19090188f},
    {-0.24188840f, 0.99706507f},
    {-0.81409955f, 0.91437590f},
    {0.19984126f, 0.78641367f},
    {0.14383161f, -0.14100790f},
}};

int ClampedTexel(double coord, int size) {
  return int(std::clamp(std::floor(coord), 0.0, double(size - 1)));
}

// tDepthMap.SampleLevel(PointSampler, uv, 0): the texel containing uv,
// clamp addressing.
double SampleLevelPoint(const ShadowMapView& tDepthMap, double u, double v) {
  return tDepthMap.depth(ClampedTexel(u * tDepthMap.width(), tDepthMap.width()),
                         ClampedTexel(v * tDepthMap.height(), tDepthMap.height()));
}

// tDepthMap.SampleCmpLevelZero(PCF_Sampler, uv, zReceiver) with a linear
// LESS_EQUAL comparison filter and clamp addressing: the four texels whose
// centres surround uv, each 1 when zReceiver <= depth, bilinearly weighted.
double SampleCmpLevelZero(const ShadowMapView& tDepthMap, double u, double v, double zReceiver) {
  const double tx = u * tDepthMap.width() - 0.5;
  const double ty = v * tDepthMap.height() - 0.5;
  const double x0 = std::floor(tx);
  const double y0 = std::floor(ty);
  double result = 0.0;
  for (int dy = 0; dy <= 1; ++dy) {
    for (int dx = 0; dx <= 1; ++dx) {
      const double wx = dx == 1 ? tx - x0 : 1.0 - (tx - x0);
      const double wy = dy == 1 ? ty - y0 : 1.0 - (ty - y0);
      const int i = ClampedTexel(x0 + dx + 0.5, tDepthMap.width());
      const int j = ClampedTexel(y0 + dy + 0.5, tDepthMap.height());
      result += wx * wy * (zReceiver <= tDepthMap.depth(i, j) ? 1.0 : 0.0);
    }
  }
  return result;
}

// float PenumbraSize(float zReceiver, float zBlocker) //Parallel plane estimation
double PenumbraSize(double zReceiver, double zBlocker) {
  return (zReceiver - zBlocker) / zBlocker;
}

// void FindBlocker(out float avgBlockerDepth, out float numBlockers, float2 uv, float zReceiver)
void FindBlocker(const ShadowMapView& tDepthMap, double& avgBlockerDepth, double& numBlockers,
                 double u, double v, double zReceiver) {
  // This uses similar triangles to compute what
  // area of the shadow map we should search
  double searchWidth = LIGHT_SIZE_UV * (zReceiver - NEAR_PLANE) / zReceiver;

  double blockerSum = 0;
  numBlockers = 0;

  for (int i = 0; i < BLOCKER_SEARCH_NUM_SAMPLES; ++i) {
    double shadowMapDepth = SampleLevelPoint(tDepthMap, u + poissonDisk[i][0] * searchWidth,
                                             v + poissonDisk[i][1] * searchWidth);
    if (shadowMapDepth < zReceiver) {
      blockerSum += shadowMapDepth;
      numBlockers++;
    }
  }

  avgBlockerDepth = blockerSum / numBlockers;
}

// float PCF_Filter(float2 uv, float zReceiver, float filterRadiusUV)
double PCF_Filter(const ShadowMapView& tDepthMap, double u, double v, double zReceiver,
                  double filterRadiusUV) {
  double sum = 0.0;
  for (int i = 0; i < PCF_NUM_SAMPLES; ++i) {
    // float2 offset = poissonDisk[i] * filterRadiusUV;
    double offsetX = poissonDisk[i][0] * filterRadiusUV;
    double offsetY = poissonDisk[i][1] * filterRadiusUV;
    sum += SampleCmpLevelZero(tDepthMap, u + offsetX, v + offsetY, zReceiver);
  }
  return sum / PCF_NUM_SAMPLES;
}

}  // namespace

const std::array<Point2, 16>& whitepaper_poisson_disk() {
  return poissonDisk;
}

// float PCSS(Texture2D shadowMapTex, float4 coords)
double whitepaper_pcss(const ShadowMapView& shadowMapTex, double u, double v, double z_receiver) {
  // float2 uv = coords.xy;
  // float zReceiver = coords.z; // Assumed to be eye-space z in this code
  double zReceiver = z_receiver;

  // STEP 1: blocker search
  double avgBlockerDepth = 0;
  double numBlockers = 0;
  FindBlocker(shadowMapTex, avgBlockerDepth, numBlockers, u, v, zReceiver);

  if (numBlockers < 1)
    // There are no occluders so early out (this saves filtering)
    return 1.0;

  // STEP 2: penumbra size
  double penumbraRatio = PenumbraSize(zReceiver, avgBlockerDepth);
  double filterRadiusUV = penumbraRatio * LIGHT_SIZE_UV * NEAR_PLANE / z_receiver;

  // STEP 3: filtering
  return PCF_Filter(shadowMapTex, u, v, zReceiver, filterRadiusUV);
}

}  // namespace penumbra::reference
