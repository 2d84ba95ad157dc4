struct penumbra_ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
};

uniform penumbra_ShadowParams penumbra_params;

uniform sampler2D penumbra_shadow_depth;

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

float penumbra_shadow_compare_point(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0;
    float param = z_receiver;
    return float(penumbra_shadow_reference(param) <= textureLod(penumbra_shadow_depth, uv, 0.0).x);
}

float penumbra_shadow_visibility(vec3 query)
{
    vec2 param = query.xy;
    float param_1 = query.z;
    float _87 = penumbra_shadow_compare_point(param, param_1);
    return _87;
}

float penumbra_receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _107 = penumbra_shadow_visibility(param);
    return _107;
}

float penumbra_visibility(vec4 light_clip_position)
{
    vec2 pixel = vec2(0.0);
    penumbra_texel_reads = 0.0;
    vec4 param = light_clip_position;
    vec3 query = penumbra_clip_to_query(param);
    vec3 param_1 = query;
    vec2 param_2 = pixel;
    float _142 = penumbra_receiver_visibility(param_1, param_2);
    return _142;
}
