// Depth pass in the shape of the emitted hlsl_dx10 / hlsl_dx9 depth.vert:
// depth.vert's projection, then Direct3D's y flip (and, for Direct3D 9,
// SPIRV-Cross's half-pixel offset). D3D9 selects the Direct3D 9 shape.
#ifdef D3D9
#include "d3d9_params.hlsl"
uniform float4 gl_HalfPixel;
#else
#include "d3d10_params.hlsl"
#endif
#define CLIP_POSITION SV_Position

struct Output
{
    float light_z : TEXCOORD0;
    float4 position : CLIP_POSITION;
};

Output main(float3 position : TEXCOORD0)
{
    float n = params_light.z;
    float f = params_sampling.w;
    float xy_scale = (2.0f * n) / params_light.y;
    Output output;
    output.position = float4(position.xy * xy_scale, ((position.z - n) * f) / (f - n), position.z);
#ifdef D3D9
    output.position.x = output.position.x - gl_HalfPixel.x * output.position.w;
    output.position.y = output.position.y + gl_HalfPixel.y * output.position.w;
#endif
    output.position.y = -output.position.y;
    output.light_z = position.z;
    return output;
}
