#version 450
// Full-screen pass: one triangle (-1,-1), (3,-1), (-1,3) in clip space.
// Vertices come from a buffer because Direct3D 9 has no vertex index.
layout(location = 0) in vec2 position;

void main() {
  gl_Position = vec4(position, 0.0, 1.0);
}
