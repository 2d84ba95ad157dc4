#version 330

out vec2 screen_uv;
layout(location = 0) in vec2 position;

void main()
{
    screen_uv = (position * 0.5) + vec2(0.5);
    gl_Position = vec4(position, 0.0, 1.0);
    gl_Position.z = 2.0 * gl_Position.z - gl_Position.w;
}

