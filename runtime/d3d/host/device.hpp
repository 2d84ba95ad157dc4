// The Direct3D host's view of one Direct3D device (9, 10 or 11): resources
// named by the job list's integer ids, and one draw at a time described in
// full. Names of formats, registers and sampler states are the reflection's
// (index.json), so the job writer copies them from a record unchanged and
// each device maps them to its API here, on Windows.
//
// Lifecycle: create_*_device() once; then any order of create_texture,
// upload, create_buffer, create_shader, draw, copy and read; release frees an
// id. Every call returns an empty string on success or one line saying what
// failed (the API call and its HRESULT), and leaves the device usable.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::d3dhost {

// What a texture is for.
enum class Usage {
  target,  // a colour render target the shaders may also read (query outputs,
           // min-max levels and the mipmapped min-max chain, the D3D9 map)
  depth,   // D3D9: a depth-stencil surface only (FORMAT D3DFMT_D24X8);
           // D3D10/11: the shadow map, a typeless texture (FORMAT
           // DXGI_FORMAT_R32_TYPELESS, R24G8_TYPELESS or R16_TYPELESS) with a
           // D32_FLOAT, D24_UNORM_S8_UINT or D16_UNORM depth-stencil view and
           // shader-resource views of the format each binding names
  input,   // shader-read only, filled by upload (receivers, disks, a map given)
};

enum class Stage { vertex, pixel };

struct TextureDesc {
  std::string format;  // as the reflection names it: "D3DFMT_R32F", "DXGI_FORMAT_R32G32_FLOAT"
  int width = 0;       // of level 0
  int height = 0;
  int levels = 1;  // every level is created; level l is max(1, size >> l)
  Usage usage = Usage::input;
  int layers = 0;  // 0: a 2D texture; n: a 2D array of n layers (no Direct3D 9)
};

// The reflection's sampler state (shader_contract.hpp's SamplerState).
struct SamplerDesc {
  std::string filter = "nearest";   // nearest | linear
  std::string mip_filter = "none";  // none | nearest
  std::string address = "clamp_to_edge";
  bool comparison = false;     // LESS_EQUAL comparison (D3D10/11 only)
  bool greater_equal = false;  // with comparison: GREATER_EQUAL instead (a reversed-Z map)
};

// One vertex element: "TEXCOORD0" as SEMANTIC "TEXCOORD", index 0.
struct InputElement {
  std::string semantic;  // the reflection's semantic, e.g. "TEXCOORD0"
  std::string format;    // "D3DDECLTYPE_FLOAT3", "DXGI_FORMAT_R32G32_FLOAT"
  unsigned offset = 0;   // bytes into the vertex
};

// A D3D9 float4 constant register.
struct Constant {
  Stage stage = Stage::pixel;
  std::string reg;  // "c6"
  std::array<float, 4> value{};
};

// A float4 member of a D3D10/11 constant buffer.
struct BlockMember {
  Stage stage = Stage::pixel;
  std::string reg;          // the block's register, "b0"
  unsigned block_size = 0;  // bytes of the whole block
  unsigned offset = 0;      // bytes
  std::array<float, 4> value{};
};

// A texture read by the pixel shader.
struct TextureBind {
  std::string reg;  // D3D9: the sampler register "s1"; D3D10/11: "t1"
  int texture = 0;
  std::string view_format;  // D3D10/11: the shader-resource view's format; D3D9: empty
};

struct SamplerBind {
  std::string reg;  // "s1"
  SamplerDesc state;
};

// One draw into level `colour_level` of `colour` (and/or `depth`), cleared
// first when asked, with the viewport covering that level. Triangle lists,
// no culling; depth test LESS (GREATER with `depth_greater`) with writes
// when `depth` is set, else off.
struct Draw {
  std::optional<int> colour;
  int colour_level = 0;
  std::optional<int> depth;
  std::optional<std::array<float, 4>> clear_colour;
  std::optional<float> clear_depth;
  bool depth_greater = false;
  int vs = 0;
  int ps = 0;
  std::vector<InputElement> inputs;
  int vertices = 0;                  // a buffer id
  unsigned stride = 0;               // bytes
  unsigned count = 0;                // vertices
  std::vector<Constant> constants;   // D3D9
  std::vector<BlockMember> members;  // D3D10/11
  std::vector<TextureBind> textures;
  std::vector<SamplerBind> samplers;
};

class Device {
 public:
  virtual ~Device() = default;
  // "Direct3D 9 on <adapter>", "Direct3D 11 (feature level 11_0) on <adapter>".
  virtual std::string description() const = 0;
  virtual std::string create_texture(int id, const TextureDesc& desc) = 0;
  // `texels`: the level's rows top first, each texel's channels in
  // R, G, B, A order as 32-bit floats (D3DFMT_A32B32G32R32F too); an
  // array's layers one after another.
  virtual std::string upload(int id, int level, const std::vector<float>& texels) = 0;
  virtual std::string create_buffer(int id, const std::vector<float>& data) = 0;
  virtual std::string create_shader(int id, Stage stage,
                                    const std::vector<unsigned char>& code) = 0;
  virtual std::string draw(const Draw& draw) = 0;
  // Level `src_level` of `src` into level `dst_level` of `dst`, at its texel
  // (0, 0): the same format, the source no larger (a min-max level into a
  // chain level of a power-of-two side).
  virtual std::string copy(int src, int src_level, int dst, int dst_level) = 0;
  // Level `level`'s texels as upload() takes them; `error` says why not.
  virtual std::vector<float> read(int id, int level, std::string& error) = 0;
  virtual void release(int id) = 0;
};

// Each returns no device and says why in `error`.
std::unique_ptr<Device> create_d3d9_device(std::string& error);
std::unique_ptr<Device> create_d3d10_device(std::string& error);
// Feature level 11_0, or 10_0 when `feature_level_10` (hlsl_dx10 through D3D11).
std::unique_ptr<Device> create_d3d11_device(bool feature_level_10, std::string& error);

}  // namespace penumbra::d3dhost
