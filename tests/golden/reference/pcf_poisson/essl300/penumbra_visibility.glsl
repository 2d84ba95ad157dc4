const vec2 penumbra_PCF_DISK[16] = vec2[](vec2(-0.94201624393463134765625, -0.39906215667724609375), vec2(0.94558608531951904296875, -0.768907248973846435546875), vec2(-0.094184100627899169921875, -0.929388701915740966796875), vec2(0.34495937824249267578125, 0.29387760162353515625), vec2(-0.91588580608367919921875, 0.4577143192291259765625), vec2(-0.8154423236846923828125, -0.87912464141845703125), vec2(-0.38277542591094970703125, 0.2767684459686279296875), vec2(0.9748439788818359375, 0.7564837932586669921875), vec2(0.4432332515716552734375, -0.9751155376434326171875), vec2(0.5374298095703125, -0.473734200000762939453125), vec2(-0.2649691104888916015625, -0.418930232524871826171875), vec2(0.79197514057159423828125, 0.19090187549591064453125), vec2(-0.24188840389251708984375, 0.997065067291259765625), vec2(-0.8140995502471923828125, 0.91437590122222900390625), vec2(0.1998412609100341796875, 0.786413669586181640625), vec2(0.14383161067962646484375, -0.141007900238037109375));

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
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = penumbra_PCF_DISK[i] * penumbra_params.sampling.x;
        vec2 param = query.xy + offset;
        float param_1 = query.z;
        float _164 = penumbra_shadow_compare_bilinear(param, param_1);
        sum += _164;
    }
    return sum / 16.0;
}

float penumbra_receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _193 = penumbra_shadow_visibility(param);
    return _193;
}

float penumbra_visibility(vec4 light_clip_position)
{
    vec2 pixel = vec2(0.0);
    penumbra_texel_reads = 0.0;
    vec4 param = light_clip_position;
    vec3 query = penumbra_clip_to_query(param);
    vec3 param_1 = query;
    vec2 param_2 = pixel;
    float _228 = penumbra_receiver_visibility(param_1, param_2);
    return _228;
}
