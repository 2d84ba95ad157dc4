// PCSS steps 2 and 3 (the NVIDIA PCSS whitepaper's names), shared by pcss and
// pcss_minmax: penumbra size and filtering over PCF_DISK.
#ifndef PENUMBRA_PCSS_FILTER_GLSL
#define PENUMBRA_PCSS_FILTER_GLSL

#include "common/disks.glsl"

// Parallel plane estimation.
float PenumbraSize(float zReceiver, float zBlocker) {
  return (zReceiver - zBlocker) / zBlocker;
}

float PCF_Filter(vec2 uv, float zReceiver, float filterRadiusUV) {
  float sum = 0.0;
  PENUMBRA_SAMPLE_LOOP for (int i = 0; i < PCF_NUM_SAMPLES; ++i) {
    vec2 offset = PCF_DISK_POINT(i) * filterRadiusUV;
    sum += shadow_compare_bilinear(uv + offset, PENUMBRA_PLANE_Z(zReceiver, offset));
  }
  return sum / float(PCF_NUM_SAMPLES);
}

#endif
