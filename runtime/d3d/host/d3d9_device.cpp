// Direct3D 9 for penumbra_d3d_host: a HAL device with hardware vertex
// processing on a hidden window of its own, windowed, no back buffer drawn
// to. Every draw renders into a texture level the job names.
#include <d3d9.h>
#include <windows.h>
#include <wrl/client.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "device.hpp"

namespace penumbra::d3dhost {
namespace {

using Microsoft::WRL::ComPtr;

std::string failed(const std::string& call, HRESULT hr) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%08x", static_cast<unsigned>(hr));
  return call + ": " + hex;
}

std::string at(int id, int level) {
  return " (id " + std::to_string(id) + ", level " + std::to_string(level) + ")";
}

// The formats the reflection names for hlsl_dx9. The colour ones store a
// texel's channels in R, G, B, A order, as upload() and read() take them.
struct Format {
  const char* name;
  D3DFORMAT format;
  int channels;  // 0: depth-stencil
};
constexpr Format kFormats[] = {
    {"D3DFMT_R32F", D3DFMT_R32F, 1},
    {"D3DFMT_G32R32F", D3DFMT_G32R32F, 2},
    {"D3DFMT_A32B32G32R32F", D3DFMT_A32B32G32R32F, 4},
    {"D3DFMT_D24X8", D3DFMT_D24X8, 0},
};

struct Texture {
  TextureDesc desc;
  Format format{};
  ComPtr<IDirect3DTexture9> texture;  // target, input
  ComPtr<IDirect3DSurface9> depth;    // depth

  int width(int level) const { return std::max(1, desc.width >> level); }
  int height(int level) const { return std::max(1, desc.height >> level); }
  std::size_t row_bytes(int level) const {
    return static_cast<std::size_t>(width(level)) * format.channels * sizeof(float);
  }
};

struct Buffer {
  ComPtr<IDirect3DVertexBuffer9> buffer;
  std::size_t bytes = 0;
};

struct Shader {
  ComPtr<IDirect3DVertexShader9> vertex;
  ComPtr<IDirect3DPixelShader9> pixel;
};

// "c6" -> 6; false unless `reg` is `prefix` and a number below `limit`.
bool parse_register(const std::string& reg, char prefix, unsigned limit, unsigned& index) {
  if (reg.size() < 2 || reg.size() > 4 || reg[0] != prefix) return false;
  if (!std::all_of(reg.begin() + 1, reg.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return false;
  }
  index = static_cast<unsigned>(std::stoul(reg.substr(1)));
  return index < limit;
}

// An InputElement as a D3DVERTEXELEMENT9 of stream 0.
std::string vertex_element(const InputElement& input, D3DVERTEXELEMENT9& element) {
  const std::size_t digits = input.semantic.find_last_not_of("0123456789") + 1;
  const std::string name = input.semantic.substr(0, digits);
  const std::string index = input.semantic.substr(digits);
  if ((name != "TEXCOORD" && name != "POSITION") || index.size() > 2) {
    return "semantic '" + input.semantic + "' (allowed: TEXCOORDn, POSITIONn)";
  }
  const char* types[] = {"D3DDECLTYPE_FLOAT1", "D3DDECLTYPE_FLOAT2", "D3DDECLTYPE_FLOAT3",
                         "D3DDECLTYPE_FLOAT4"};
  const auto type = std::find(std::begin(types), std::end(types), input.format);
  if (type == std::end(types)) {
    return "vertex format '" + input.format + "' (allowed: D3DDECLTYPE_FLOAT1 to FLOAT4)";
  }
  element = {0,
             static_cast<WORD>(input.offset),
             static_cast<BYTE>(D3DDECLTYPE_FLOAT1 + (type - std::begin(types))),
             D3DDECLMETHOD_DEFAULT,
             static_cast<BYTE>(name == "TEXCOORD" ? D3DDECLUSAGE_TEXCOORD : D3DDECLUSAGE_POSITION),
             static_cast<BYTE>(index.empty() ? 0 : std::stoi(index))};
  return {};
}

// D3DCOLOR has 8 bits a channel, so a float target is cleared to what the
// nearest byte gives: exact for the 0 and 1 that the job writer clears to.
D3DCOLOR clear_value(const std::array<float, 4>& rgba) {
  DWORD c[4];
  for (int i = 0; i < 4; ++i) {
    c[i] = static_cast<DWORD>(std::clamp(rgba[i], 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  return D3DCOLOR_ARGB(c[3], c[0], c[1], c[2]);
}

template <class T>
T* find(std::map<int, T>& map, int id) {
  const auto found = map.find(id);
  return found == map.end() ? nullptr : &found->second;
}

// The device's hidden window; a member before the device, so destroyed after it.
struct Window {
  HWND handle = nullptr;
  Window() = default;
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
  ~Window() {
    if (handle) DestroyWindow(handle);
  }
};

class D3d9Device final : public Device {
 public:
  std::string open();
  std::string description() const override { return "Direct3D 9 on " + adapter_; }
  std::string create_texture(int id, const TextureDesc& desc) override;
  std::string upload(int id, int level, const std::vector<float>& texels) override;
  std::string create_buffer(int id, const std::vector<float>& data) override;
  std::string create_shader(int id, Stage stage, const std::vector<unsigned char>& code) override;
  std::string draw(const Draw& draw) override;
  std::string copy(int src, int src_level, int dst, int dst_level) override;
  std::vector<float> read(int id, int level, std::string& error) override {
    std::vector<float> texels;
    error = read_level(id, level, texels);
    return texels;
  }
  // An id created again names the new resource.
  void release(int id) override {
    textures_.erase(id);
    buffers_.erase(id);
    shaders_.erase(id);
  }

 private:
  // A colour texture's level surface; `error` names the id and the level.
  ComPtr<IDirect3DSurface9> level_surface(int id, int level, std::string& error);
  // A system-memory surface of a level's size and format, which render
  // targets, never locked themselves, are filled and read through.
  std::string staging(int id, int level, ComPtr<IDirect3DSurface9>& surface);
  std::string read_level(int id, int level, std::vector<float>& texels);
  std::string submit(const Draw& draw, std::vector<DWORD>& bound);
  std::string bind_samplers(const Draw& draw, int colour, std::vector<DWORD>& bound);

  Window window_;
  ComPtr<IDirect3D9> d3d_;
  ComPtr<IDirect3DDevice9> device_;
  std::string adapter_;
  std::map<int, Texture> textures_;
  std::map<int, Buffer> buffers_;
  std::map<int, Shader> shaders_;
  std::map<std::string, ComPtr<IDirect3DVertexDeclaration9>> declarations_;
};

std::string D3d9Device::open() {
  window_.handle = CreateWindowA("STATIC", "penumbra_d3d_host", WS_OVERLAPPEDWINDOW, 0, 0, 64, 64,
                                 nullptr, nullptr, GetModuleHandleA(nullptr), nullptr);
  if (!window_.handle) return "CreateWindowA: error " + std::to_string(GetLastError());
  // Not Attach: mingw-w64's adds a reference to the one Direct3DCreate9 returns.
  *d3d_.GetAddressOf() = Direct3DCreate9(D3D_SDK_VERSION);
  if (!d3d_) return "Direct3DCreate9 returned no object";
  D3DADAPTER_IDENTIFIER9 identifier{};
  HRESULT hr = d3d_->GetAdapterIdentifier(D3DADAPTER_DEFAULT, 0, &identifier);
  if (FAILED(hr)) return failed("GetAdapterIdentifier", hr);
  adapter_ = identifier.Description;
  D3DPRESENT_PARAMETERS present{};  // the back buffer is never drawn to
  present.BackBufferWidth = present.BackBufferHeight = 64;
  present.SwapEffect = D3DSWAPEFFECT_DISCARD;
  present.hDeviceWindow = window_.handle;
  present.Windowed = TRUE;
  hr = d3d_->CreateDevice(D3DADAPTER_DEFAULT, D3DDEVTYPE_HAL, window_.handle,
                          D3DCREATE_HARDWARE_VERTEXPROCESSING, &present, &device_);
  return FAILED(hr) ? failed("CreateDevice (HAL, hardware vertex processing)", hr) : "";
}

std::string D3d9Device::create_texture(int id, const TextureDesc& desc) {
  release(id);
  const auto format = std::find_if(std::begin(kFormats), std::end(kFormats),
                                   [&](const Format& f) { return desc.format == f.name; });
  const std::string what = " (id " + std::to_string(id) + ", " + desc.format + " " +
                           std::to_string(desc.width) + "x" + std::to_string(desc.height) + ", " +
                           std::to_string(desc.levels) + " levels)";
  if (format == std::end(kFormats)) {
    return "texture" + what +
           ": allowed formats D3DFMT_R32F, D3DFMT_G32R32F, D3DFMT_A32B32G32R32F, D3DFMT_D24X8";
  }
  if (desc.layers != 0) return "texture" + what + ": Direct3D 9 has no texture arrays";
  const bool depth = desc.usage == Usage::depth;
  if (depth != (format->channels == 0) || desc.levels < 1 || (depth && desc.levels != 1) ||
      desc.width < 1 || desc.height < 1) {
    return "texture" + what +
           ": only D3DFMT_D24X8 is a depth surface (1 level); sizes and levels are >= 1";
  }
  Texture texture{desc, *format, nullptr, nullptr};
  HRESULT hr;
  if (depth) {
    // Not discarded: a depth pass may span several draws.
    hr = device_->CreateDepthStencilSurface(desc.width, desc.height, D3DFMT_D24X8,
                                            D3DMULTISAMPLE_NONE, 0, FALSE, &texture.depth, nullptr);
    if (FAILED(hr)) return failed("CreateDepthStencilSurface" + what, hr);
  } else {
    const bool target = desc.usage == Usage::target;
    if (target) {
      D3DDISPLAYMODE mode{};
      hr = d3d_->GetAdapterDisplayMode(D3DADAPTER_DEFAULT, &mode);
      if (FAILED(hr)) return failed("GetAdapterDisplayMode", hr);
      hr = d3d_->CheckDeviceFormat(D3DADAPTER_DEFAULT, D3DDEVTYPE_HAL, mode.Format,
                                   D3DUSAGE_RENDERTARGET, D3DRTYPE_TEXTURE, format->format);
      if (FAILED(hr)) return failed("CheckDeviceFormat (render target" + what, hr);
    }
    hr = device_->CreateTexture(
        desc.width, desc.height, desc.levels, target ? D3DUSAGE_RENDERTARGET : 0, format->format,
        target ? D3DPOOL_DEFAULT : D3DPOOL_MANAGED, &texture.texture, nullptr);
    if (FAILED(hr)) return failed("CreateTexture" + what, hr);
  }
  textures_.emplace(id, std::move(texture));
  return {};
}

ComPtr<IDirect3DSurface9> D3d9Device::level_surface(int id, int level, std::string& error) {
  const Texture* texture = find(textures_, id);
  if (!texture || !texture->texture) {
    error = "no colour texture with id " + std::to_string(id);
    return nullptr;
  }
  if (level < 0 || level >= texture->desc.levels) {
    error = "texture " + std::to_string(id) + " has no level " + std::to_string(level);
    return nullptr;
  }
  ComPtr<IDirect3DSurface9> surface;
  const HRESULT hr = texture->texture->GetSurfaceLevel(level, &surface);
  if (FAILED(hr)) error = failed("GetSurfaceLevel" + at(id, level), hr);
  return surface;
}

std::string D3d9Device::staging(int id, int level, ComPtr<IDirect3DSurface9>& surface) {
  const Texture& texture = textures_.at(id);
  const HRESULT hr = device_->CreateOffscreenPlainSurface(
      texture.width(level), texture.height(level), texture.format.format, D3DPOOL_SYSTEMMEM,
      &surface, nullptr);
  return FAILED(hr) ? failed("CreateOffscreenPlainSurface" + at(id, level), hr) : "";
}

std::string D3d9Device::upload(int id, int level, const std::vector<float>& texels) {
  std::string error;
  ComPtr<IDirect3DSurface9> surface = level_surface(id, level, error);
  if (!surface) return "upload: " + error;
  const Texture& texture = textures_.at(id);
  const std::size_t row = texture.row_bytes(level);
  const int rows = texture.height(level);
  if (texels.size() * sizeof(float) != row * rows) {
    return "upload" + at(id, level) + ": " + std::to_string(texels.size()) +
           " floats, the level holds " + std::to_string(row / sizeof(float) * rows);
  }
  const bool target = texture.desc.usage == Usage::target;
  ComPtr<IDirect3DSurface9> fill = surface;
  if (target && !(error = staging(id, level, fill)).empty()) return error;
  D3DLOCKED_RECT locked;
  HRESULT hr = fill->LockRect(&locked, nullptr, 0);
  if (FAILED(hr)) return failed("LockRect" + at(id, level), hr);
  for (int y = 0; y < rows; ++y) {
    std::memcpy(static_cast<char*>(locked.pBits) + y * locked.Pitch,
                reinterpret_cast<const char*>(texels.data()) + y * row, row);
  }
  hr = fill->UnlockRect();
  if (FAILED(hr)) return failed("UnlockRect" + at(id, level), hr);
  if (target) {
    hr = device_->UpdateSurface(fill.Get(), nullptr, surface.Get(), nullptr);
    if (FAILED(hr)) return failed("UpdateSurface" + at(id, level), hr);
  }
  return {};
}

std::string D3d9Device::create_buffer(int id, const std::vector<float>& data) {
  release(id);
  const std::string what = " (id " + std::to_string(id) + ")";
  if (data.empty()) return "buffer" + what + " is empty";
  Buffer buffer{nullptr, data.size() * sizeof(float)};
  HRESULT hr = device_->CreateVertexBuffer(buffer.bytes, D3DUSAGE_WRITEONLY, 0, D3DPOOL_MANAGED,
                                           &buffer.buffer, nullptr);
  if (FAILED(hr)) return failed("CreateVertexBuffer" + what, hr);
  void* bytes = nullptr;
  hr = buffer.buffer->Lock(0, 0, &bytes, 0);
  if (FAILED(hr)) return failed("IDirect3DVertexBuffer9::Lock" + what, hr);
  std::memcpy(bytes, data.data(), buffer.bytes);
  hr = buffer.buffer->Unlock();
  if (FAILED(hr)) return failed("IDirect3DVertexBuffer9::Unlock" + what, hr);
  buffers_.emplace(id, std::move(buffer));
  return {};
}

std::string D3d9Device::create_shader(int id, Stage stage, const std::vector<unsigned char>& code) {
  release(id);
  const std::string what = " (id " + std::to_string(id) + ")";
  if (code.empty() || code.size() % sizeof(DWORD) != 0) {
    return "shader" + what + ": " + std::to_string(code.size()) +
           " bytes is not Direct3D 9 bytecode (whole DWORDs)";
  }
  // The API reads DWORDs; the file's bytes may not be aligned for that.
  std::vector<DWORD> words(code.size() / sizeof(DWORD));
  std::memcpy(words.data(), code.data(), code.size());
  Shader shader;
  const HRESULT hr = stage == Stage::vertex
                         ? device_->CreateVertexShader(words.data(), &shader.vertex)
                         : device_->CreatePixelShader(words.data(), &shader.pixel);
  if (FAILED(hr)) {
    return failed(stage == Stage::vertex ? "CreateVertexShader" + what : "CreatePixelShader" + what,
                  hr);
  }
  shaders_.emplace(id, std::move(shader));
  return {};
}

std::string D3d9Device::draw(const Draw& draw) {
  std::vector<DWORD> bound;
  const std::string error = submit(draw, bound);
  // Unbound, a texture can be the target of a later draw.
  for (const DWORD sampler : bound) device_->SetTexture(sampler, nullptr);
  return error;
}

std::string D3d9Device::submit(const Draw& draw, std::vector<DWORD>& bound) {
  if (!draw.colour) return "draw: Direct3D 9 draws need a colour target";
  std::string error;
  ComPtr<IDirect3DSurface9> colour = level_surface(*draw.colour, draw.colour_level, error);
  if (!colour) return "draw colour: " + error;
  const Texture& target = textures_.at(*draw.colour);
  if (target.desc.usage != Usage::target) {
    return "draw: texture " + std::to_string(*draw.colour) + " is not a render target";
  }
  IDirect3DSurface9* depth = nullptr;
  const int width = target.width(draw.colour_level);
  const int height = target.height(draw.colour_level);
  if (draw.depth) {
    const Texture* surface = find(textures_, *draw.depth);
    if (!surface || !surface->depth) {
      return "draw: no depth surface with id " + std::to_string(*draw.depth);
    }
    if (surface->desc.width < width || surface->desc.height < height) {
      return "draw: depth surface " + std::to_string(*draw.depth) + " is smaller than the target";
    }
    depth = surface->depth.Get();
  }
  if (draw.clear_depth && !depth) return "draw: clear_depth without a depth surface";
  const Shader* vs = find(shaders_, draw.vs);
  if (!vs || !vs->vertex) return "draw: no vertex shader with id " + std::to_string(draw.vs);
  const Shader* ps = find(shaders_, draw.ps);
  if (!ps || !ps->pixel) return "draw: no pixel shader with id " + std::to_string(draw.ps);
  const Buffer* vertices = find(buffers_, draw.vertices);
  if (!vertices) return "draw: no buffer with id " + std::to_string(draw.vertices);
  if (draw.count == 0 || draw.count % 3 != 0 || draw.stride == 0 ||
      std::size_t{draw.stride} * draw.count > vertices->bytes) {
    return "draw: " + std::to_string(draw.count) + " vertices of " + std::to_string(draw.stride) +
           " bytes (whole triangles) do not fit buffer " + std::to_string(draw.vertices);
  }

  // Declarations are few (one per pass kind): made once each.
  std::string key;
  for (const InputElement& input : draw.inputs) {
    key += input.semantic + " " + input.format + " " + std::to_string(input.offset) + ";";
  }
  ComPtr<IDirect3DVertexDeclaration9>& declaration = declarations_[key];
  if (!declaration) {
    std::vector<D3DVERTEXELEMENT9> elements(draw.inputs.size() + 1);
    for (std::size_t i = 0; i < draw.inputs.size(); ++i) {
      error = vertex_element(draw.inputs[i], elements[i]);
      if (!error.empty()) return "draw input: " + error;
    }
    elements.back() = D3DDECL_END();
    const HRESULT hr = device_->CreateVertexDeclaration(elements.data(), &declaration);
    if (FAILED(hr)) return failed("CreateVertexDeclaration (" + key + ")", hr);
  }

  auto check = [&error](HRESULT hr, const std::string& call) {
    if (FAILED(hr) && error.empty()) error = failed(call, hr);
  };
  const D3DVIEWPORT9 viewport{0, 0, DWORD(width), DWORD(height), 0.0f, 1.0f};
  const std::string what = " (colour " + std::to_string(*draw.colour) + " level " +
                           std::to_string(draw.colour_level) + ")";
  check(device_->SetRenderTarget(0, colour.Get()), "SetRenderTarget" + what);
  check(device_->SetViewport(&viewport), "SetViewport" + what);
  check(device_->SetDepthStencilSurface(depth), "SetDepthStencilSurface" + what);
  const std::pair<D3DRENDERSTATETYPE, DWORD> states[] = {
      {D3DRS_ZENABLE, depth ? D3DZB_TRUE : D3DZB_FALSE},
      {D3DRS_ZFUNC, DWORD(draw.depth_greater ? D3DCMP_GREATER : D3DCMP_LESS)},
      {D3DRS_ZWRITEENABLE, TRUE},
      {D3DRS_CULLMODE, D3DCULL_NONE},
      {D3DRS_ALPHABLENDENABLE, FALSE},
  };
  for (const auto& [state, value] : states) {
    check(device_->SetRenderState(state, value), "SetRenderState " + std::to_string(state));
  }
  const DWORD clear =
      (draw.clear_colour ? D3DCLEAR_TARGET : 0) | (draw.clear_depth ? D3DCLEAR_ZBUFFER : 0);
  if (clear) {
    check(device_->Clear(0, nullptr, clear, draw.clear_colour ? clear_value(*draw.clear_colour) : 0,
                         draw.clear_depth.value_or(1.0f), 0),
          "Clear" + what);
  }
  check(device_->SetVertexDeclaration(declaration.Get()), "SetVertexDeclaration (" + key + ")");
  check(device_->SetStreamSource(0, vertices->buffer.Get(), 0, draw.stride),
        "SetStreamSource (buffer " + std::to_string(draw.vertices) + ")");
  check(device_->SetVertexShader(vs->vertex.Get()),
        "SetVertexShader (id " + std::to_string(draw.vs) + ")");
  check(device_->SetPixelShader(ps->pixel.Get()),
        "SetPixelShader (id " + std::to_string(draw.ps) + ")");
  for (const Constant& constant : draw.constants) {
    unsigned reg = 0;
    if (!parse_register(constant.reg, 'c', 256, reg)) {
      return "draw: constant register '" + constant.reg + "' (allowed: c0 to c255)";
    }
    const bool vertex = constant.stage == Stage::vertex;
    check(vertex ? device_->SetVertexShaderConstantF(reg, constant.value.data(), 1)
                 : device_->SetPixelShaderConstantF(reg, constant.value.data(), 1),
          std::string(vertex ? "SetVertexShaderConstantF " : "SetPixelShaderConstantF ") +
              constant.reg);
  }
  if (!error.empty()) return error;
  error = bind_samplers(draw, *draw.colour, bound);
  if (!error.empty()) return error;

  check(device_->BeginScene(), "BeginScene");
  if (!error.empty()) return error;
  check(device_->DrawPrimitive(D3DPT_TRIANGLELIST, 0, draw.count / 3), "DrawPrimitive" + what);
  check(device_->EndScene(), "EndScene");
  return error;
}

std::string D3d9Device::bind_samplers(const Draw& draw, int colour, std::vector<DWORD>& bound) {
  for (const TextureBind& bind : draw.textures) {
    unsigned sampler = 0;
    if (!parse_register(bind.reg, 's', 16, sampler)) {
      return "draw: texture register '" + bind.reg + "' (allowed: s0 to s15)";
    }
    const Texture* texture = find(textures_, bind.texture);
    if (!texture || !texture->texture) {
      return "draw: no colour texture with id " + std::to_string(bind.texture);
    }
    if (bind.texture == colour) {
      return "draw: texture " + std::to_string(colour) + " is both read and the render target";
    }
    const HRESULT hr = device_->SetTexture(sampler, texture->texture.Get());
    if (FAILED(hr)) {
      return failed("SetTexture " + bind.reg + " (id " + std::to_string(bind.texture) + ")", hr);
    }
    bound.push_back(sampler);
  }
  for (const SamplerBind& bind : draw.samplers) {
    const SamplerDesc& s = bind.state;
    unsigned sampler = 0;
    if (!parse_register(bind.reg, 's', 16, sampler)) {
      return "draw: sampler register '" + bind.reg + "' (allowed: s0 to s15)";
    }
    if (s.comparison) return "sampler " + bind.reg + ": Direct3D 9 has no comparison sampler";
    const bool linear = s.filter == "linear";
    const bool mipmapped = s.mip_filter == "nearest";
    if ((!linear && s.filter != "nearest") || (!mipmapped && s.mip_filter != "none") ||
        s.address != "clamp_to_edge") {
      return "sampler " + bind.reg + ": " + s.filter + " " + s.mip_filter + " " + s.address +
             " (allowed: nearest|linear none|nearest clamp_to_edge)";
    }
    const DWORD filter = linear ? D3DTEXF_LINEAR : D3DTEXF_POINT;
    const std::pair<D3DSAMPLERSTATETYPE, DWORD> states[] = {
        {D3DSAMP_ADDRESSU, D3DTADDRESS_CLAMP},
        {D3DSAMP_ADDRESSV, D3DTADDRESS_CLAMP},
        {D3DSAMP_ADDRESSW, D3DTADDRESS_CLAMP},
        {D3DSAMP_MINFILTER, filter},
        {D3DSAMP_MAGFILTER, filter},
        {D3DSAMP_MIPFILTER, mipmapped ? D3DTEXF_POINT : D3DTEXF_NONE},
        {D3DSAMP_MAXMIPLEVEL, 0},
    };
    for (const auto& [state, value] : states) {
      const HRESULT hr = device_->SetSamplerState(sampler, state, value);
      if (FAILED(hr)) {
        return failed("SetSamplerState " + bind.reg + " " + std::to_string(state), hr);
      }
    }
  }
  return {};
}

// The source level lands at texel (0, 0) of the destination level, which may
// be larger: the min-max levels go into the power-of-two chain this way.
std::string D3d9Device::copy(int src, int src_level, int dst, int dst_level) {
  std::string error;
  ComPtr<IDirect3DSurface9> from = level_surface(src, src_level, error);
  if (!from) return "copy source: " + error;
  ComPtr<IDirect3DSurface9> to = level_surface(dst, dst_level, error);
  if (!to) return "copy destination: " + error;
  const Texture& a = textures_.at(src);
  const Texture& b = textures_.at(dst);
  const std::string what = " (id " + std::to_string(src) + " level " + std::to_string(src_level) +
                           " to id " + std::to_string(dst) + " level " + std::to_string(dst_level) +
                           ")";
  if (a.desc.usage != Usage::target || b.desc.usage != Usage::target ||
      a.desc.format != b.desc.format || a.width(src_level) > b.width(dst_level) ||
      a.height(src_level) > b.height(dst_level)) {
    return "copy" + what + ": both must be render targets of one format, the source no larger";
  }
  const RECT rect{0, 0, a.width(src_level), a.height(src_level)};
  const HRESULT hr = device_->StretchRect(from.Get(), nullptr, to.Get(), &rect, D3DTEXF_POINT);
  return FAILED(hr) ? failed("StretchRect" + what, hr) : "";
}

std::string D3d9Device::read_level(int id, int level, std::vector<float>& texels) {
  std::string error;
  ComPtr<IDirect3DSurface9> surface = level_surface(id, level, error);
  if (!surface) return "read: " + error;
  const Texture& texture = textures_.at(id);
  if (texture.desc.usage == Usage::target) {
    ComPtr<IDirect3DSurface9> copy;
    if (!(error = staging(id, level, copy)).empty()) return error;
    const HRESULT hr = device_->GetRenderTargetData(surface.Get(), copy.Get());
    if (FAILED(hr)) return failed("GetRenderTargetData" + at(id, level), hr);
    surface = copy;
  }
  D3DLOCKED_RECT locked;
  HRESULT hr = surface->LockRect(&locked, nullptr, D3DLOCK_READONLY);
  if (FAILED(hr)) return failed("LockRect" + at(id, level), hr);
  const std::size_t row = texture.row_bytes(level);
  const int rows = texture.height(level);
  texels.resize(row / sizeof(float) * rows);
  for (int y = 0; y < rows; ++y) {
    std::memcpy(reinterpret_cast<char*>(texels.data()) + y * row,
                static_cast<const char*>(locked.pBits) + y * locked.Pitch, row);
  }
  hr = surface->UnlockRect();
  return FAILED(hr) ? failed("UnlockRect" + at(id, level), hr) : "";
}

}  // namespace

std::unique_ptr<Device> create_d3d9_device(std::string& error) {
  auto device = std::make_unique<D3d9Device>();
  error = device->open();
  if (!error.empty()) return nullptr;
  return device;
}

}  // namespace penumbra::d3dhost
