// compare.frag in the shape of the emitted hlsl_dx10 query.frag: separate
// Texture2D and SamplerState / SamplerComparisonState named as SPIRV-Cross
// names them. shadow_depth's read only scales the result by step(0, d) = 1
// (the map holds d in [0, 1]): bound and used, it leaves the output exact.
#include "d3d10_params.hlsl"

Texture2D<float4> shadow_depth : register(t1);
SamplerState _shadow_depth_sampler : register(s1);
Texture2D<float4> shadow_cmp : register(t2);
SamplerComparisonState _shadow_cmp_sampler : register(s2);
Texture2D<float4> receivers : register(t3);
SamplerState _receivers_sampler : register(s3);

float4 main(float2 screen_uv : TEXCOORD0) : SV_Target0
{
    float3 query = receivers.SampleLevel(_receivers_sampler, screen_uv, 0.0f).xyz;
    float reference = (query.z - params_sampling.y) * params_sampling.z;
    float depth = shadow_depth.SampleLevel(_shadow_depth_sampler, query.xy, 0.0f).x;
    return (shadow_cmp.SampleCmpLevelZero(_shadow_cmp_sampler, query.xy, reference) *
            step(0.0f, depth)).xxxx;
}
