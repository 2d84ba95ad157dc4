const vec2 penumbra_POISSON_DISK[16] = vec2[](vec2(-0.94201624393463134765625, -0.39906215667724609375), vec2(0.94558608531951904296875, -0.768907248973846435546875), vec2(-0.094184100627899169921875, -0.929388701915740966796875), vec2(0.34495937824249267578125, 0.29387760162353515625), vec2(-0.91588580608367919921875, 0.4577143192291259765625), vec2(-0.8154423236846923828125, -0.87912464141845703125), vec2(-0.38277542591094970703125, 0.2767684459686279296875), vec2(0.9748439788818359375, 0.7564837932586669921875), vec2(0.4432332515716552734375, -0.9751155376434326171875), vec2(0.5374298095703125, -0.473734200000762939453125), vec2(-0.2649691104888916015625, -0.418930232524871826171875), vec2(0.79197514057159423828125, 0.19090187549591064453125), vec2(-0.24188840389251708984375, 0.997065067291259765625), vec2(-0.8140995502471923828125, 0.91437590122222900390625), vec2(0.1998412609100341796875, 0.786413669586181640625), vec2(0.14383161067962646484375, -0.141007900238037109375));

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
uniform sampler2DShadow penumbra_shadow_cmp;

float penumbra_texel_reads;

vec3 penumbra_clip_to_query(vec4 light_clip_position)
{
    vec2 ndc = light_clip_position.xy / vec2(light_clip_position.w);
    return vec3(0.5 + (0.5 * ndc.x), 0.5 + (0.5 * ndc.y), light_clip_position.w);
}

float penumbra_shadow_depth_point(vec2 uv)
{
    penumbra_texel_reads += 1.0;
    return textureLod(penumbra_shadow_depth, uv, 0.0).x * penumbra_params.sampling.w;
}

void penumbra_FindBlocker(inout float avgBlockerDepth, inout float numBlockers, vec2 uv, float zReceiver)
{
    float searchWidth = (penumbra_params.light.w * (zReceiver - penumbra_params.light.z)) / zReceiver;
    float blockerSum = 0.0;
    numBlockers = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = penumbra_POISSON_DISK[i] * searchWidth;
        vec2 param = uv + offset;
        float _252 = penumbra_shadow_depth_point(param);
        float shadowMapDepth = _252;
        bool blocks = shadowMapDepth < (zReceiver - penumbra_params.sampling.y);
        blockerSum += (blocks ? shadowMapDepth : 0.0);
        numBlockers += float(blocks);
    }
    float _274;
    if (numBlockers > 0.0)
    {
        _274 = blockerSum / numBlockers;
    }
    else
    {
        _274 = zReceiver;
    }
    avgBlockerDepth = _274;
}

float penumbra_PenumbraSize(float zReceiver, float zBlocker)
{
    return (zReceiver - zBlocker) / zBlocker;
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
    vec3 _120 = vec3(uv, reference);
    return textureLod(penumbra_shadow_cmp, vec3(_120.xy, _120.z), 0.0);
}

float penumbra_PCF_Filter(vec2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = penumbra_POISSON_DISK[i] * filterRadiusUV;
        vec2 param = uv + offset;
        float param_1 = zReceiver;
        float _210 = penumbra_shadow_compare_bilinear(param, param_1);
        sum += _210;
    }
    return sum / 16.0;
}

float penumbra_PCSS(vec3 coords)
{
    vec2 uv = coords.xy;
    float zReceiver = coords.z;
    if (!(zReceiver > penumbra_params.light.z))
    {
        return 1.0;
    }
    float avgBlockerDepth = 0.0;
    float numBlockers = 0.0;
    vec2 param_2 = uv;
    float param_3 = zReceiver;
    float param;
    float param_1;
    penumbra_FindBlocker(param, param_1, param_2, param_3);
    avgBlockerDepth = param;
    numBlockers = param_1;
    if (numBlockers < 1.0)
    {
        return 1.0;
    }
    float param_4 = zReceiver;
    float param_5 = max(avgBlockerDepth, penumbra_params.light.z);
    float penumbraRatio = penumbra_PenumbraSize(param_4, param_5);
    float filterRadiusUV = ((penumbraRatio * penumbra_params.light.w) * penumbra_params.light.z) / coords.z;
    vec2 param_6 = uv;
    float param_7 = zReceiver;
    float param_8 = filterRadiusUV;
    float _339 = penumbra_PCF_Filter(param_6, param_7, param_8);
    return _339;
}

float penumbra_shadow_visibility(vec3 query)
{
    vec3 param = query;
    float _344 = penumbra_PCSS(param);
    return _344;
}

float penumbra_receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _364 = penumbra_shadow_visibility(param);
    return _364;
}

float penumbra_visibility(vec4 light_clip_position)
{
    vec2 pixel = vec2(0.0);
    penumbra_texel_reads = 0.0;
    vec4 param = light_clip_position;
    vec3 query = penumbra_clip_to_query(param);
    vec3 param_1 = query;
    vec2 param_2 = pixel;
    float _398 = penumbra_receiver_visibility(param_1, param_2);
    return _398;
}
