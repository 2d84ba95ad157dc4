#version 330

const vec2 POISSON_DISK[16] = vec2[](vec2(-0.3564817905426025390625, -0.7736518383026123046875), vec2(0.7706091403961181640625, -0.476450383663177490234375), vec2(0.040970109403133392333984375, -0.96095740795135498046875), vec2(0.013376322574913501739501953125, 0.997840583324432373046875), vec2(0.591416180133819580078125, -0.011377436108887195587158203125), vec2(0.1291187703609466552734375, -0.02888503484427928924560546875), vec2(0.3763323128223419189453125, 0.4415138661861419677734375), vec2(0.549356281757354736328125, 0.793806552886962890625), vec2(-0.011186738498508930206298828125, 0.4573924839496612548828125), vec2(0.784348905086517333984375, 0.3635326325893402099609375), vec2(-0.797832071781158447265625, -0.535640716552734375), vec2(0.480243146419525146484375, -0.69643151760101318359375), vec2(-0.750289142131805419921875, 0.620359599590301513671875), vec2(-0.95311391353607177734375, -0.03544120490550994873046875), vec2(-0.4556185305118560791015625, -0.09509353339672088623046875), vec2(0.12933044135570526123046875, -0.57352435588836669921875));

struct ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
    vec4 camera_inverse_0;
    vec4 camera_inverse_1;
    vec4 camera_inverse_2;
    vec4 camera_inverse_3;
    vec4 light_view_proj_0;
    vec4 light_view_proj_1;
    vec4 light_view_proj_2;
    vec4 light_view_proj_3;
    vec4 camera_depth_range;
};

uniform ShadowParams params;

uniform sampler2D shadow_depth;
uniform sampler2DShadow shadow_cmp;
uniform sampler2D camera_depth;

in vec2 screen_uv;
layout(location = 0) out vec4 visibility;
float penumbra_texel_reads;

float shadow_linear(float stored)
{
    return ((1.0 - stored) * params.light.z) + (stored * params.sampling.w);
}

vec3 clip_to_query(vec4 light_clip_position)
{
    vec2 ndc = light_clip_position.xy / vec2(light_clip_position.w);
    float param = (0.5 * (light_clip_position.z / light_clip_position.w)) + 0.5;
    return vec3(0.5 + (0.5 * ndc.x), 0.5 + (0.5 * ndc.y), shadow_linear(param));
}

float shadow_depth_point(vec2 uv)
{
    penumbra_texel_reads += 1.0;
    float param = textureLod(shadow_depth, uv, 0.0).x;
    return shadow_linear(param);
}

void FindBlocker(inout float avgBlockerDepth, inout float numBlockers, vec2 uv, float zReceiver)
{
    float searchWidth = params.light.w * (zReceiver - params.light.z);
    float blockerSum = 0.0;
    numBlockers = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = POISSON_DISK[i] * searchWidth;
        vec2 param = uv + offset;
        float _262 = shadow_depth_point(param);
        float shadowMapDepth = _262;
        bool blocks = shadowMapDepth < (zReceiver - params.sampling.y);
        blockerSum += (blocks ? shadowMapDepth : 0.0);
        numBlockers += float(blocks);
    }
    float _284;
    if (numBlockers > 0.0)
    {
        _284 = blockerSum / numBlockers;
    }
    else
    {
        _284 = zReceiver;
    }
    avgBlockerDepth = _284;
}

float shadow_encode(float z)
{
    return (z - params.light.z) / (params.sampling.w - params.light.z);
}

float shadow_reference(float z_receiver)
{
    float param = z_receiver - params.sampling.y;
    return shadow_encode(param);
}

float shadow_compare_bilinear(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0;
    float param = z_receiver;
    float reference = shadow_reference(param);
    vec3 _140 = vec3(uv, reference);
    return textureLod(shadow_cmp, vec3(_140.xy, _140.z), 0.0);
}

float PCF_Filter(vec2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = POISSON_DISK[i] * filterRadiusUV;
        vec2 param = uv + offset;
        float param_1 = zReceiver;
        float _223 = shadow_compare_bilinear(param, param_1);
        sum += _223;
    }
    return sum / 16.0;
}

float PCSS(vec3 coords)
{
    vec2 uv = coords.xy;
    float zReceiver = coords.z;
    if (!(zReceiver > params.light.z))
    {
        return 1.0;
    }
    float avgBlockerDepth = 0.0;
    float numBlockers = 0.0;
    vec2 param_2 = uv;
    float param_3 = zReceiver;
    float param;
    float param_1;
    FindBlocker(param, param_1, param_2, param_3);
    avgBlockerDepth = param;
    numBlockers = param_1;
    if (numBlockers < 1.0)
    {
        return 1.0;
    }
    float filterRadiusUV = params.light.w * (zReceiver - max(avgBlockerDepth, params.light.z));
    vec2 param_4 = uv;
    float param_5 = zReceiver;
    float param_6 = filterRadiusUV;
    float _339 = PCF_Filter(param_4, param_5, param_6);
    return _339;
}

float shadow_visibility(vec3 query)
{
    vec3 param = query;
    float _344 = PCSS(param);
    return _344;
}

float receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _364 = shadow_visibility(param);
    return _364;
}

void main()
{
    penumbra_texel_reads = 0.0;
    float depth = textureLod(camera_depth, screen_uv, 0.0).x;
    vec4 clip = vec4((2.0 * screen_uv.x) - 1.0, (screen_uv.y - 0.5) / 0.5, (depth * params.camera_depth_range.x) + params.camera_depth_range.y, 1.0);
    mat4 camera_inverse = mat4(vec4(params.camera_inverse_0), vec4(params.camera_inverse_1), vec4(params.camera_inverse_2), vec4(params.camera_inverse_3));
    mat4 light_view_proj = mat4(vec4(params.light_view_proj_0), vec4(params.light_view_proj_1), vec4(params.light_view_proj_2), vec4(params.light_view_proj_3));
    vec4 world = camera_inverse * clip;
    vec4 param = light_view_proj * (world / vec4(world.w));
    vec3 query = clip_to_query(param);
    if (depth == params.camera_depth_range.z)
    {
        query = vec3(0.5, 0.5, 0.0);
    }
    vec3 param_1 = query;
    vec2 param_2 = floor(screen_uv * params.screen_size.xy);
    float _526 = receiver_visibility(param_1, param_2);
    float visible = _526;
    visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}

