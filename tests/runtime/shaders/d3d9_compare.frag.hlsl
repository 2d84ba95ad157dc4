// compare.frag in the shape of the emitted hlsl_dx9 query.frag: $Global
// constants, sampler2D on the R32F map, tex2Dlod point reads and the
// bilinear comparison made in the shader, as the emitted
// shadow_compare_bilinear makes it.
#include "d3d9_params.hlsl"

uniform sampler2D shadow_depth;
uniform sampler2D receivers;

float lit(float2 uv, float reference)
{
    return float(reference <= tex2Dlod(shadow_depth, float4(uv, 0.0f, 0.0f)).x);
}

float4 main(float2 screen_uv : TEXCOORD0) : COLOR0
{
    float3 query = tex2Dlod(receivers, float4(screen_uv, 0.0f, 0.0f)).xyz;
    float reference = (query.z - params_sampling.y) * params_sampling.z;
    float2 texel = (query.xy * params_shadow_map_size.xy) - 0.5f.xx;
    float2 corner = floor(texel);
    float2 weight = texel - corner;
    float2 uv00 = (corner + 0.5f.xx) * params_shadow_map_size.zw;
    float2 uv11 = uv00 + params_shadow_map_size.zw;
    float lit00 = lit(uv00, reference);
    float lit10 = lit(float2(uv11.x, uv00.y), reference);
    float lit01 = lit(float2(uv00.x, uv11.y), reference);
    float lit11 = lit(uv11, reference);
    return lerp(lerp(lit00, lit10, weight.x), lerp(lit01, lit11, weight.x), weight.y).xxxx;
}
