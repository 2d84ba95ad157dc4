#version 330
// Query pass vertex stage in the shape of the emitted glsl330
// fullscreen.vert, without its clip z fix-up (see gl330_depth.vert).
layout(location = 0) in vec2 position;
out vec2 screen_uv;

void main()
{
    screen_uv = (position * 0.5) + vec2(0.5);
    gl_Position = vec4(position, 0.0, 1.0);
}
