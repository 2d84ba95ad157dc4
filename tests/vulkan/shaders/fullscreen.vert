#version 450
// Query pass: the full-screen triangle, already in clip space.
layout(location = 0) in vec2 position;

void main() { gl_Position = vec4(position, 0.0, 1.0); }
