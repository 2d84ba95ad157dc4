const vec2 penumbra_POISSON_DISK[16] = vec2[](vec2(-0.3564817905426025390625, -0.7736518383026123046875), vec2(0.7706091403961181640625, -0.476450383663177490234375), vec2(0.040970109403133392333984375, -0.96095740795135498046875), vec2(0.013376322574913501739501953125, 0.997840583324432373046875), vec2(0.591416180133819580078125, -0.011377436108887195587158203125), vec2(0.1291187703609466552734375, -0.02888503484427928924560546875), vec2(0.3763323128223419189453125, 0.4415138661861419677734375), vec2(0.549356281757354736328125, 0.793806552886962890625), vec2(-0.011186738498508930206298828125, 0.4573924839496612548828125), vec2(0.784348905086517333984375, 0.3635326325893402099609375), vec2(-0.797832071781158447265625, -0.535640716552734375), vec2(0.480243146419525146484375, -0.69643151760101318359375), vec2(-0.750289142131805419921875, 0.620359599590301513671875), vec2(-0.95311391353607177734375, -0.03544120490550994873046875), vec2(-0.4556185305118560791015625, -0.09509353339672088623046875), vec2(0.12933044135570526123046875, -0.57352435588836669921875));

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

float penumbra_shadow_linear(float stored)
{
    return ((1.0 - stored) * penumbra_params.light.z) + (stored * penumbra_params.sampling.w);
}

vec3 penumbra_clip_to_query(vec4 light_clip_position)
{
    vec2 ndc = light_clip_position.xy / vec2(light_clip_position.w);
    float param = (0.5 * (light_clip_position.z / light_clip_position.w)) + 0.5;
    return vec3(0.5 + (0.5 * ndc.x), 0.5 + (0.5 * ndc.y), penumbra_shadow_linear(param));
}

float penumbra_shadow_depth_point(vec2 uv)
{
    penumbra_texel_reads += 1.0;
    float param = textureLod(penumbra_shadow_depth, uv, 0.0).x;
    return penumbra_shadow_linear(param);
}

void penumbra_FindBlocker(inout float avgBlockerDepth, inout float numBlockers, vec2 uv, float zReceiver)
{
    float searchWidth = penumbra_params.light.w * (zReceiver - penumbra_params.light.z);
    float blockerSum = 0.0;
    numBlockers = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = penumbra_POISSON_DISK[i] * searchWidth;
        vec2 param = uv + offset;
        float _266 = penumbra_shadow_depth_point(param);
        float shadowMapDepth = _266;
        bool blocks = shadowMapDepth < (zReceiver - penumbra_params.sampling.y);
        blockerSum += (blocks ? shadowMapDepth : 0.0);
        numBlockers += float(blocks);
    }
    float _288;
    if (numBlockers > 0.0)
    {
        _288 = blockerSum / numBlockers;
    }
    else
    {
        _288 = zReceiver;
    }
    avgBlockerDepth = _288;
}

float penumbra_shadow_encode(float z)
{
    return (z - penumbra_params.light.z) / (penumbra_params.sampling.w - penumbra_params.light.z);
}

float penumbra_shadow_reference(float z_receiver)
{
    float param = z_receiver - penumbra_params.sampling.y;
    return penumbra_shadow_encode(param);
}

float penumbra_shadow_compare_bilinear(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0;
    float param = z_receiver;
    float reference = penumbra_shadow_reference(param);
    vec3 _144 = vec3(uv, reference);
    return textureLod(penumbra_shadow_cmp, vec3(_144.xy, _144.z), 0.0);
}

float penumbra_PCF_Filter(vec2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = penumbra_POISSON_DISK[i] * filterRadiusUV;
        vec2 param = uv + offset;
        float param_1 = zReceiver;
        float _227 = penumbra_shadow_compare_bilinear(param, param_1);
        sum += _227;
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
    float filterRadiusUV = penumbra_params.light.w * (zReceiver - max(avgBlockerDepth, penumbra_params.light.z));
    vec2 param_4 = uv;
    float param_5 = zReceiver;
    float param_6 = filterRadiusUV;
    float _343 = penumbra_PCF_Filter(param_4, param_5, param_6);
    return _343;
}

float penumbra_shadow_visibility(vec3 query)
{
    vec3 param = query;
    float _348 = penumbra_PCSS(param);
    return _348;
}

float penumbra_receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _368 = penumbra_shadow_visibility(param);
    return _368;
}

float penumbra_visibility(vec4 light_clip_position)
{
    vec2 pixel = vec2(0.0);
    penumbra_texel_reads = 0.0;
    vec4 param = light_clip_position;
    vec3 query = penumbra_clip_to_query(param);
    vec3 param_1 = query;
    vec2 param_2 = pixel;
    float _409 = penumbra_receiver_visibility(param_1, param_2);
    return _409;
}
