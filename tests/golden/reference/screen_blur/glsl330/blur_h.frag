#version 330

const float BLUR_WEIGHTS[9] = float[](0.02763055078685283660888671875, 0.0662822425365447998046875, 0.1238315403461456298828125, 0.18017382919788360595703125, 0.20416368544101715087890625, 0.18017382919788360595703125, 0.1238315403461456298828125, 0.0662822425365447998046875, 0.02763055078685283660888671875);

struct ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
};

uniform ShadowParams params;

uniform sampler2D screen_factor;

layout(location = 0) out vec4 blurred;
in vec2 screen_uv;

float blur_factor(vec2 screen_uv_1, vec2 axis)
{
    vec2 pixel = floor(screen_uv_1 * params.screen_size.xy);
    float sum = 0.0;
    for (int k = -4; k <= 4; k++)
    {
        vec2 uv = ((pixel + (axis * float(k))) + vec2(0.5)) * params.screen_size.zw;
        float weight = BLUR_WEIGHTS[k + 4];
        sum += (weight * textureLod(screen_factor, uv, 0.0).x);
    }
    return sum;
}

void main()
{
    vec2 param = screen_uv;
    vec2 param_1 = vec2(1.0, 0.0);
    blurred = vec4(blur_factor(param, param_1), 0.0, 0.0, 0.0);
}

