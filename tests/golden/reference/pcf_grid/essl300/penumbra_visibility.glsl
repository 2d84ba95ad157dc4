layout(std140) uniform penumbra_ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
} penumbra_params;

uniform highp sampler2DShadow penumbra_shadow_cmp;

float penumbra_texel_reads;

vec3 penumbra_clip_to_query(vec4 light_clip_position)
{
    vec2 ndc = light_clip_position.xy / vec2(light_clip_position.w);
    return vec3(0.5 + (0.5 * ndc.x), 0.5 + (0.5 * ndc.y), light_clip_position.w);
}

float penumbra_shadow_reference(float z_receiver)
{
    return (z_receiver - penumbra_params.sampling.y) * penumbra_params.sampling.z;
}

float penumbra_shadow_compare_bilinear(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0;
    float param = z_receiver;
    float reference = penumbra_shadow_reference(param);
    vec3 _76 = vec3(uv, reference);
    return textureLod(penumbra_shadow_cmp, vec3(_76.xy, _76.z), 0.0);
}

float penumbra_shadow_visibility(vec3 query)
{
    float sum = 0.0;
    for (int j = -1; j <= 1; j++)
    {
        for (int i = -1; i <= 1; i++)
        {
            vec2 param = query.xy + (vec2(float(i), float(j)) * penumbra_params.shadow_map_size.zw);
            float param_1 = query.z;
            float _121 = penumbra_shadow_compare_bilinear(param, param_1);
            sum += _121;
        }
    }
    return sum / 9.0;
}

float penumbra_receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _151 = penumbra_shadow_visibility(param);
    return _151;
}

float penumbra_visibility(vec4 light_clip_position)
{
    vec2 pixel = vec2(0.0);
    penumbra_texel_reads = 0.0;
    vec4 param = light_clip_position;
    vec3 query = penumbra_clip_to_query(param);
    vec3 param_1 = query;
    vec2 param_2 = pixel;
    float _187 = penumbra_receiver_visibility(param_1, param_2);
    return _187;
}
