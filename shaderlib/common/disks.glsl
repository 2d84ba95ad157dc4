// The Poisson disks' points: PCF_DISK_POINT(i) and BLOCKER_DISK_POINT(i).
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
#define PCF_DISK_POINT(i) PENUMBRA_DISK_TEXEL(pcf_disk, i, PCF_NUM_SAMPLES)
#endif
#ifdef BLOCKER_SEARCH_NUM_SAMPLES
layout(set = 0, binding = PENUMBRA_SLOT_BLOCKER_DISK) uniform sampler2D blocker_disk;
#define BLOCKER_DISK_POINT(i) PENUMBRA_DISK_TEXEL(blocker_disk, i, BLOCKER_SEARCH_NUM_SAMPLES)
#endif
#else
#define PCF_DISK_POINT(i) PCF_DISK[i]
#define BLOCKER_DISK_POINT(i) BLOCKER_DISK[i]
#endif

#endif
