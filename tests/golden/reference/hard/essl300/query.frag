#version 300 es
precision highp float;
precision highp int;

layout(std140) uniform ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
} params;

uniform highp sampler2D shadow_depth;
uniform highp sampler2D receivers;

in vec2 screen_uv;
layout(location = 0) out vec4 visibility;
float penumbra_texel_reads;

float shadow_reference(float z_receiver)
{
    return (z_receiver - params.sampling.y) * params.sampling.z;
}

float shadow_compare_point(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0;
    float param = z_receiver;
    return float(shadow_reference(param) <= textureLod(shadow_depth, uv, 0.0).x);
}

float shadow_visibility(vec3 query)
{
    vec2 param = query.xy;
    float param_1 = query.z;
    float _78 = shadow_compare_point(param, param_1);
    return _78;
}

float receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _98 = shadow_visibility(param);
    return _98;
}

void main()
{
    penumbra_texel_reads = 0.0;
    vec3 query = textureLod(receivers, screen_uv, 0.0).xyz;
    vec3 param = query;
    vec2 param_1 = floor(screen_uv * params.screen_size.xy);
    float _121 = receiver_visibility(param, param_1);
    float visible = _121;
    visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}

