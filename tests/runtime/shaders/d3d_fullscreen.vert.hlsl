// Query pass vertex stage in the shape of the emitted hlsl_dx10 / hlsl_dx9
// fullscreen.vert: screen_uv from the unflipped position, then the y flip
// (and, for Direct3D 9, the half-pixel offset in $Global).
#ifdef D3D9
uniform float4 gl_HalfPixel;
#endif

struct Output
{
    float2 screen_uv : TEXCOORD0;
    float4 position : SV_Position;
};

Output main(float2 position : TEXCOORD0)
{
    Output output;
    output.screen_uv = (position * 0.5f) + 0.5f.xx;
    output.position = float4(position, 0.0f, 1.0f);
#ifdef D3D9
    output.position.x = output.position.x - gl_HalfPixel.x * output.position.w;
    output.position.y = output.position.y + gl_HalfPixel.y * output.position.w;
#endif
    output.position.y = -output.position.y;
    return output;
}
