#version 450

layout(binding = 0, std140) uniform ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
} params;

layout(binding = 2) uniform sampler2DShadow shadow_cmp;
layout(binding = 3) uniform sampler2D receivers;

layout(location = 0) in vec2 screen_uv;
layout(location = 0) out vec4 visibility;
float penumbra_texel_reads;

float shadow_reference(float z_receiver)
{
    return (z_receiver - params.sampling.y) * params.sampling.z;
}

float shadow_compare_bilinear(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0;
    float param = z_receiver;
    float reference = shadow_reference(param);
    vec3 _67 = vec3(uv, reference);
    return textureLod(shadow_cmp, vec3(_67.xy, _67.z), 0.0);
}

float shadow_visibility(vec3 query)
{
    float sum = 0.0;
    for (int j = -1; j <= 1; j++)
    {
        for (int i = -1; i <= 1; i++)
        {
            vec2 param = query.xy + (vec2(float(i), float(j)) * params.shadow_map_size.zw);
            float param_1 = query.z;
            float _112 = shadow_compare_bilinear(param, param_1);
            sum += _112;
        }
    }
    return sum / 9.0;
}

float receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _142 = shadow_visibility(param);
    return _142;
}

void main()
{
    penumbra_texel_reads = 0.0;
    vec3 query = textureLod(receivers, screen_uv, 0.0).xyz;
    vec3 param = query;
    vec2 param_1 = floor(screen_uv * params.screen_size.xy);
    float _167 = receiver_visibility(param, param_1);
    float visible = _167;
    visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}

