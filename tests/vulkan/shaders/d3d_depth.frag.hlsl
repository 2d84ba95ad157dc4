// Depth pass in the shape of the emitted hlsl_dx10 / hlsl_dx9 depth.frag
// (D3D9: $Global constants and a float4 COLOR0 output), with SV_Depth where
// the emitted Direct3D 9 file says DEPTH, which glslang does not make the
// built-in fragment depth; D3D9_DEPTH_SEMANTIC keeps DEPTH.
#ifdef D3D9
#include "d3d9_params.hlsl"
#define TARGET COLOR0
typedef float4 target_type;
#else
#include "d3d10_params.hlsl"
#define TARGET SV_Target0
typedef float target_type;
#endif

#ifdef D3D9_DEPTH_SEMANTIC
#define FRAGMENT_DEPTH DEPTH
#else
#define FRAGMENT_DEPTH SV_Depth
#endif

struct Output
{
    target_type depth_out : TARGET;
    float depth : FRAGMENT_DEPTH;
};

Output main(float light_z : TEXCOORD0)
{
    float d = light_z * params_sampling.z;
    Output output;
    output.depth_out = (target_type)d;
    output.depth = d;
    return output;
}
