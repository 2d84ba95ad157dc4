#version 450

layout(binding = 7) uniform sampler2D scene_colour;
layout(binding = 6) uniform sampler2D screen_factor;

layout(location = 0) in vec2 screen_uv;
layout(location = 0) out vec4 colour;

void main()
{
    vec4 scene = textureLod(scene_colour, screen_uv, 0.0);
    float factor = textureLod(screen_factor, screen_uv, 0.0).x;
    colour = vec4(scene.xyz * factor, scene.w);
}

