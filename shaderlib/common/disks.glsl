// The sample sets' points: PCF_DISK_POINT(i) and BLOCKER_DISK_POINT(i).
// Most targets index the constant arrays of variant.glsl. Where
// PENUMBRA_DISK_TEXTURES is set (Direct3D 9), the points are texels of the
// one-row RG32F textures pcf_disk and blocker_disk, filled by the engine from
// the reflection: Shader Model 3 compilers turn an indexed constant array
// into a compare-select per element, which no longer fits 512 slots.
#ifndef PENUMBRA_DISKS_GLSL
#define PENUMBRA_DISKS_GLSL

#if PENUMBRA_DISK_TEXTURES
// Point i sits at texel (i, 0); the texel centre is read exactly.
#define PENUMBRA_DISK_TEXEL(disk, i, count) \
  textureLod(disk, vec2((float(i) + 0.5) / float(count), 0.5), 0.0).xy
#ifdef PCF_NUM_SAMPLES
layout(set = 0, binding = PENUMBRA_SLOT_PCF_DISK) uniform sampler2D pcf_disk;
#define PCF_DISK_BAKED(i) PENUMBRA_DISK_TEXEL(pcf_disk, i, PCF_NUM_SAMPLES)
#endif
#ifdef BLOCKER_SEARCH_NUM_SAMPLES
layout(set = 0, binding = PENUMBRA_SLOT_BLOCKER_DISK) uniform sampler2D blocker_disk;
#define BLOCKER_DISK_BAKED(i) PENUMBRA_DISK_TEXEL(blocker_disk, i, BLOCKER_SEARCH_NUM_SAMPLES)
#endif
#else
#define PCF_DISK_BAKED(i) PCF_DISK[i]
#define BLOCKER_DISK_BAKED(i) BLOCKER_DISK[i]
#endif

#if PENUMBRA_ROTATION_IGN
// The `rotation` key: each pixel places the baked points anew. Round sets
// turn by an angle, square sets (PENUMBRA_SQUARE_SAMPLES) shift on the
// square's torus, which keeps their footprint the light's square.

// The pixel's placement, set by penumbra_begin_pixel(): (cos, sin) of the
// turn, or the square's shift in [0, 1)^2.
vec2 penumbra_frame;

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post
// Processing in Call of Duty: Advanced Warfare"), its constants rounded to
// dyadic fractions: for pixels below 4096 every step is exact in float32,
// so each target, and the reference, has the same value to the bit.
float penumbra_gradient_noise(vec2 pixel) {
  return fract(52.984375 * fract(0.067138671875 * pixel.x + 0.005859375 * pixel.y));
}

void penumbra_begin_pixel(vec2 pixel) {
#if PENUMBRA_SQUARE_SAMPLES
  penumbra_frame = vec2(penumbra_gradient_noise(pixel), penumbra_gradient_noise(pixel.yx));
#else
  float angle = 6.28318530718 * penumbra_gradient_noise(pixel);
  penumbra_frame = vec2(cos(angle), sin(angle));
#endif
}

vec2 penumbra_place(vec2 point) {
#if PENUMBRA_SQUARE_SAMPLES
  return fract(point * 0.5 + 0.5 + penumbra_frame) * 2.0 - 1.0;
#else
  return vec2(point.x * penumbra_frame.x - point.y * penumbra_frame.y,
              point.x * penumbra_frame.y + point.y * penumbra_frame.x);
#endif
}

#define PCF_DISK_POINT(i) penumbra_place(PCF_DISK_BAKED(i))
#define BLOCKER_DISK_POINT(i) penumbra_place(BLOCKER_DISK_BAKED(i))
#else
#define PCF_DISK_POINT(i) PCF_DISK_BAKED(i)
#define BLOCKER_DISK_POINT(i) BLOCKER_DISK_BAKED(i)
#endif

#endif
