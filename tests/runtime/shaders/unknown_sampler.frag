#version 450
// A query program binding a name outside the shader interface.
layout(set = 0, binding = 1) uniform sampler2D shadow_mapp;
layout(location = 0) out vec4 visibility;

void main() { visibility = textureLod(shadow_mapp, vec2(0.5), 0.0); }
