#version 450
// Full-screen pass: one triangle (-1,-1), (3,-1), (-1,3) in clip space.
// Vertices come from a buffer because Direct3D 9 has no vertex index. The
// screen uv is interpolated rather than derived from gl_FragCoord, whose
// origin differs between D3D9's VPOS (pixel corner) and every other API
// (pixel centre).
layout(location = 0) in vec2 position;
layout(location = 0) out vec2 screen_uv;

void main() {
  screen_uv = position * 0.5 + 0.5;
  gl_Position = vec4(position, 0.0, 1.0);
}
