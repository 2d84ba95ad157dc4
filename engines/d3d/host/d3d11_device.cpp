// Direct3D 11 behind device.hpp's Device (docs/engines/d3d11.md): the
// hardware driver at feature level 11_0, or 10_0 for hlsl_dx10's shaders;
// resources on the device, every draw on the immediate context.
#include <d3d11.h>
#include <wrl/client.h>

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "device.hpp"
#include "dxgi_names.hpp"

namespace penumbra::d3dhost {
namespace {

using Microsoft::WRL::ComPtr;

struct Texture {
  TextureDesc desc;
  DxgiFormat format;
  ComPtr<ID3D11Texture2D> texture;
  // Views, each made when a draw first needs it.
  std::vector<ComPtr<ID3D11RenderTargetView>> targets;  // per level
  ComPtr<ID3D11DepthStencilView> depth;
  std::map<DXGI_FORMAT, ComPtr<ID3D11ShaderResourceView>> views;
};

struct Buffer {
  ComPtr<ID3D11Buffer> buffer;
  UINT bytes = 0;
};

struct Shader {
  Stage stage = Stage::pixel;
  ComPtr<ID3D11VertexShader> vertex;
  ComPtr<ID3D11PixelShader> pixel;
  std::vector<unsigned char> code;  // a vertex shader's: input layouts are checked against it
  std::map<std::string, ComPtr<ID3D11InputLayout>> layouts;  // by the draw's inputs
};

std::string texture_name(int id) {
  return "texture " + std::to_string(id);
}

class D3D11Device final : public Device {
 public:
  D3D11Device(ComPtr<ID3D11Device> device, ComPtr<ID3D11DeviceContext> context,
              D3D_FEATURE_LEVEL level, std::string description)
      : device_(std::move(device)),
        context_(std::move(context)),
        depth_copies_(level >= D3D_FEATURE_LEVEL_10_1),
        description_(std::move(description)) {}

  std::string init();
  std::string description() const override { return description_; }
  std::string create_texture(int id, const TextureDesc& desc) override;
  std::string upload(int id, int level, const std::vector<float>& texels) override;
  std::string create_buffer(int id, const std::vector<float>& data) override;
  std::string create_shader(int id, Stage stage, const std::vector<unsigned char>& code) override;
  std::string draw(const Draw& draw) override;
  std::string copy(int src, int src_level, int dst, int dst_level) override;
  std::vector<float> read(int id, int level, std::string& error) override;
  void release(int id) override;

 private:
  std::string make_texture(Texture& t, const D3D11_SUBRESOURCE_DATA* data, int id);
  std::string make_staging(const Texture& t, int level, UINT cpu_access,
                           ComPtr<ID3D11Texture2D>& staging, int id);
  std::string find_level(int id, int level, Texture*& t);
  std::string find_shader(int id, Stage stage, Shader*& s);
  std::string render_target(Texture& t, int id, int level, ID3D11RenderTargetView*& view);
  std::string depth_stencil(Texture& t, int id, ID3D11DepthStencilView*& view);
  std::string resource_view(Texture& t, int id, const std::string& view_format,
                            ID3D11ShaderResourceView*& view);
  std::string input_layout(Shader& vs, int id, const std::vector<InputElement>& inputs,
                           ID3D11InputLayout*& layout);
  std::string sampler(const SamplerDesc& desc, ID3D11SamplerState*& state);
  std::string constant_buffer(const ConstantBlock& block, ID3D11Buffer*& buffer);

  ComPtr<ID3D11Device> device_;
  ComPtr<ID3D11DeviceContext> context_;
  // Copies into a depth-stencil resource need feature level 10_1
  // (ID3D11DeviceContext::CopyResource's remarks).
  bool depth_copies_;
  std::string description_;
  ComPtr<ID3D11RasterizerState> rasterizer_;
  ComPtr<ID3D11DepthStencilState> depth_test_;
  ComPtr<ID3D11DepthStencilState> no_depth_;
  std::map<int, Texture> textures_;
  std::map<int, Buffer> buffers_;
  std::map<int, Shader> shaders_;
  std::map<SamplerSettings, ComPtr<ID3D11SamplerState>> samplers_;
  std::map<std::tuple<Stage, UINT, std::size_t>, ComPtr<ID3D11Buffer>> constants_;
};

std::string D3D11Device::init() {
  D3D11_RASTERIZER_DESC raster{};
  raster.FillMode = D3D11_FILL_SOLID;
  raster.CullMode = D3D11_CULL_NONE;
  raster.DepthClipEnable = TRUE;
  HRESULT hr = device_->CreateRasterizerState(&raster, &rasterizer_);
  if (FAILED(hr)) return failed("CreateRasterizerState", hr, "the draw state");
  // Stencil is off, but its operations must still be valid values.
  const D3D11_DEPTH_STENCILOP_DESC keep = {D3D11_STENCIL_OP_KEEP, D3D11_STENCIL_OP_KEEP,
                                           D3D11_STENCIL_OP_KEEP, D3D11_COMPARISON_ALWAYS};
  D3D11_DEPTH_STENCIL_DESC depth{};
  depth.DepthEnable = TRUE;
  depth.DepthWriteMask = D3D11_DEPTH_WRITE_MASK_ALL;
  depth.DepthFunc = D3D11_COMPARISON_LESS;
  depth.StencilReadMask = D3D11_DEFAULT_STENCIL_READ_MASK;
  depth.StencilWriteMask = D3D11_DEFAULT_STENCIL_WRITE_MASK;
  depth.FrontFace = keep;
  depth.BackFace = keep;
  if (hr = device_->CreateDepthStencilState(&depth, &depth_test_); FAILED(hr)) {
    return failed("CreateDepthStencilState", hr, "depth test");
  }
  depth.DepthEnable = FALSE;
  depth.DepthWriteMask = D3D11_DEPTH_WRITE_MASK_ZERO;
  if (hr = device_->CreateDepthStencilState(&depth, &no_depth_); FAILED(hr)) {
    return failed("CreateDepthStencilState", hr, "no depth");
  }
  return {};
}

std::string D3D11Device::make_texture(Texture& t, const D3D11_SUBRESOURCE_DATA* data, int id) {
  D3D11_TEXTURE2D_DESC desc{};
  desc.Width = static_cast<UINT>(t.desc.width);
  desc.Height = static_cast<UINT>(t.desc.height);
  desc.MipLevels = static_cast<UINT>(t.desc.levels);
  desc.ArraySize = 1;
  desc.Format = t.format.format;
  desc.SampleDesc.Count = 1;
  desc.Usage = D3D11_USAGE_DEFAULT;
  switch (t.desc.usage) {
    case Usage::target:
      desc.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
      break;
    case Usage::depth:
      desc.BindFlags = D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE;
      break;
    case Usage::input:
      desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
      break;
  }
  t.targets.resize(desc.MipLevels);
  const HRESULT hr = device_->CreateTexture2D(&desc, data, &t.texture);
  return FAILED(hr) ? failed("CreateTexture2D", hr, texture_name(id)) : std::string();
}

// A one-level CPU copy of `t`'s level `level`, same format (typeless too).
std::string D3D11Device::make_staging(const Texture& t, int level, UINT cpu_access,
                                      ComPtr<ID3D11Texture2D>& staging, int id) {
  D3D11_TEXTURE2D_DESC desc{};
  desc.Width = level_size(t.desc.width, level);
  desc.Height = level_size(t.desc.height, level);
  desc.MipLevels = 1;
  desc.ArraySize = 1;
  desc.Format = t.format.format;
  desc.SampleDesc.Count = 1;
  desc.Usage = D3D11_USAGE_STAGING;
  desc.CPUAccessFlags = cpu_access;
  const HRESULT hr = device_->CreateTexture2D(&desc, nullptr, &staging);
  return FAILED(hr) ? failed("CreateTexture2D (staging)", hr, texture_name(id)) : std::string();
}

std::string D3D11Device::find_level(int id, int level, Texture*& t) {
  t = find_id(textures_, id);
  if (!t) return "unknown " + texture_name(id);
  if (level < 0 || level >= t->desc.levels) {
    return "level " + std::to_string(level) + " of " + texture_name(id) + ", which has " +
           std::to_string(t->desc.levels);
  }
  return {};
}

std::string D3D11Device::find_shader(int id, Stage stage, Shader*& s) {
  s = find_id(shaders_, id);
  const std::string name = "shader " + std::to_string(id);
  if (!s) return "unknown " + name;
  if (s->stage != stage) return name + (stage == Stage::vertex ? " is no vs" : " is no ps");
  return {};
}

std::string D3D11Device::create_texture(int id, const TextureDesc& desc) {
  // An id in use is replaced: a failed job's release may have been skipped.
  release(id);
  Texture t;
  t.desc = desc;
  if (std::string error = check_texture(desc, t.format); !error.empty()) {
    return error + " (" + texture_name(id) + ")";
  }
  if (std::string error = make_texture(t, nullptr, id); !error.empty()) return error;
  textures_.emplace(id, std::move(t));
  return {};
}

std::string D3D11Device::upload(int id, int level, const std::vector<float>& texels) {
  Texture* t = nullptr;
  if (std::string error = find_level(id, level, t); !error.empty()) return error;
  const UINT row = level_size(t->desc.width, level) * t->format.bytes;
  const UINT rows = level_size(t->desc.height, level);
  if (texels.size() * sizeof(float) != std::size_t{row} * rows) {
    return "level " + std::to_string(level) + " of " + texture_name(id) + " takes " +
           std::to_string(row / sizeof(float) * rows) + " floats, not " +
           std::to_string(texels.size());
  }
  if (t->desc.usage != Usage::depth) {
    context_->UpdateSubresource(t->texture.Get(), level, nullptr, texels.data(), row, 0);
    return {};
  }
  // UpdateSubresource may not write a depth-stencil resource; a copy from a
  // staging texture may from feature level 10_1 on. Below that nothing may
  // write one but the pipeline and its creation, so the map is made anew
  // with the texels as its initial data (it has one level).
  if (!depth_copies_) {
    const D3D11_SUBRESOURCE_DATA data{texels.data(), row, 0};
    Texture fresh;
    fresh.desc = t->desc;
    fresh.format = t->format;
    if (std::string error = make_texture(fresh, &data, id); !error.empty()) return error;
    *t = std::move(fresh);
    return {};
  }
  ComPtr<ID3D11Texture2D> staging;
  if (std::string error = make_staging(*t, level, D3D11_CPU_ACCESS_WRITE, staging, id);
      !error.empty()) {
    return error;
  }
  D3D11_MAPPED_SUBRESOURCE mapped{};
  const HRESULT hr = context_->Map(staging.Get(), 0, D3D11_MAP_WRITE, 0, &mapped);
  if (FAILED(hr)) return failed("Map (staging)", hr, texture_name(id));
  write_rows(texels, row, mapped.pData, mapped.RowPitch);
  context_->Unmap(staging.Get(), 0);
  // A depth-stencil copy takes the whole subresource: no box.
  context_->CopySubresourceRegion(t->texture.Get(), level, 0, 0, 0, staging.Get(), 0, nullptr);
  return {};
}

std::string D3D11Device::create_buffer(int id, const std::vector<float>& data) {
  release(id);
  if (data.empty()) return "buffer " + std::to_string(id) + " is empty";
  Buffer b;
  b.bytes = static_cast<UINT>(data.size() * sizeof(float));
  D3D11_BUFFER_DESC desc{};
  desc.ByteWidth = b.bytes;
  desc.Usage = D3D11_USAGE_IMMUTABLE;
  desc.BindFlags = D3D11_BIND_VERTEX_BUFFER;
  const D3D11_SUBRESOURCE_DATA init{data.data(), 0, 0};
  const HRESULT hr = device_->CreateBuffer(&desc, &init, &b.buffer);
  if (FAILED(hr)) return failed("CreateBuffer", hr, "buffer " + std::to_string(id));
  buffers_.emplace(id, std::move(b));
  return {};
}

std::string D3D11Device::create_shader(int id, Stage stage,
                                       const std::vector<unsigned char>& code) {
  release(id);
  const std::string name = "shader " + std::to_string(id);
  if (code.empty()) return name + " is empty";
  Shader s;
  s.stage = stage;
  if (stage == Stage::vertex) {
    const HRESULT hr = device_->CreateVertexShader(code.data(), code.size(), nullptr, &s.vertex);
    if (FAILED(hr)) return failed("CreateVertexShader", hr, name);
    s.code = code;
  } else {
    const HRESULT hr = device_->CreatePixelShader(code.data(), code.size(), nullptr, &s.pixel);
    if (FAILED(hr)) return failed("CreatePixelShader", hr, name);
  }
  shaders_.emplace(id, std::move(s));
  return {};
}

std::string D3D11Device::render_target(Texture& t, int id, int level,
                                       ID3D11RenderTargetView*& view) {
  ComPtr<ID3D11RenderTargetView>& cached = t.targets[static_cast<std::size_t>(level)];
  if (!cached) {
    D3D11_RENDER_TARGET_VIEW_DESC desc{};
    desc.Format = t.format.format;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2D;
    desc.Texture2D.MipSlice = static_cast<UINT>(level);
    const HRESULT hr = device_->CreateRenderTargetView(t.texture.Get(), &desc, &cached);
    if (FAILED(hr)) return failed("CreateRenderTargetView", hr, texture_name(id));
  }
  view = cached.Get();
  return {};
}

std::string D3D11Device::depth_stencil(Texture& t, int id, ID3D11DepthStencilView*& view) {
  if (!t.depth) {
    D3D11_DEPTH_STENCIL_VIEW_DESC desc{};
    desc.Format = DXGI_FORMAT_D32_FLOAT;
    desc.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    const HRESULT hr = device_->CreateDepthStencilView(t.texture.Get(), &desc, &t.depth);
    if (FAILED(hr)) return failed("CreateDepthStencilView", hr, texture_name(id));
  }
  view = t.depth.Get();
  return {};
}

std::string D3D11Device::resource_view(Texture& t, int id, const std::string& view_format,
                                       ID3D11ShaderResourceView*& view) {
  DxgiFormat format = t.format;
  if (!view_format.empty()) {
    if (std::string error = parse_format(view_format, FormatUse::view, format); !error.empty()) {
      return error + " (" + texture_name(id) + ")";
    }
  } else if (t.desc.usage == Usage::depth) {
    return texture_name(id) + " is typeless: its binding needs a view format";
  }
  ComPtr<ID3D11ShaderResourceView>& cached = t.views[format.format];
  if (!cached) {
    D3D11_SHADER_RESOURCE_VIEW_DESC desc{};
    desc.Format = format.format;
    desc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    desc.Texture2D.MipLevels = static_cast<UINT>(t.desc.levels);
    const HRESULT hr = device_->CreateShaderResourceView(t.texture.Get(), &desc, &cached);
    if (FAILED(hr)) {
      t.views.erase(format.format);
      return failed(
          "CreateShaderResourceView", hr,
          texture_name(id) + " as " + (view_format.empty() ? t.desc.format : view_format));
    }
  }
  view = cached.Get();
  return {};
}

std::string D3D11Device::input_layout(Shader& vs, int id, const std::vector<InputElement>& inputs,
                                      ID3D11InputLayout*& layout) {
  std::string key;
  for (const InputElement& input : inputs) {
    key += input.semantic + " " + input.format + " " + std::to_string(input.offset) + ";";
  }
  ComPtr<ID3D11InputLayout>& cached = vs.layouts[key];
  if (!cached) {
    std::vector<std::string> names(inputs.size());  // SemanticName points into these
    std::vector<D3D11_INPUT_ELEMENT_DESC> elements(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      D3D11_INPUT_ELEMENT_DESC& e = elements[i];
      DxgiFormat format;
      std::string error = split_semantic(inputs[i].semantic, names[i], e.SemanticIndex);
      if (error.empty()) error = parse_format(inputs[i].format, FormatUse::vertex, format);
      if (!error.empty()) {
        vs.layouts.erase(key);
        return error + " (input of shader " + std::to_string(id) + ")";
      }
      e.SemanticName = names[i].c_str();
      e.Format = format.format;
      e.AlignedByteOffset = inputs[i].offset;
      e.InputSlotClass = D3D11_INPUT_PER_VERTEX_DATA;
    }
    const HRESULT hr =
        device_->CreateInputLayout(elements.data(), static_cast<UINT>(elements.size()),
                                   vs.code.data(), vs.code.size(), &cached);
    if (FAILED(hr)) {
      vs.layouts.erase(key);
      return failed("CreateInputLayout", hr, "shader " + std::to_string(id) + ", inputs " + key);
    }
  }
  layout = cached.Get();
  return {};
}

std::string D3D11Device::sampler(const SamplerDesc& desc, ID3D11SamplerState*& state) {
  SamplerSettings settings;
  if (std::string error = parse_sampler(desc, settings); !error.empty()) return error;
  ComPtr<ID3D11SamplerState>& cached = samplers_[settings];
  if (!cached) {
    D3D11_SAMPLER_DESC s{};
    if (settings.comparison) {
      s.Filter = settings.linear ? D3D11_FILTER_COMPARISON_MIN_MAG_LINEAR_MIP_POINT
                                 : D3D11_FILTER_COMPARISON_MIN_MAG_MIP_POINT;
    } else {
      s.Filter =
          settings.linear ? D3D11_FILTER_MIN_MAG_LINEAR_MIP_POINT : D3D11_FILTER_MIN_MAG_MIP_POINT;
    }
    s.AddressU = s.AddressV = s.AddressW = D3D11_TEXTURE_ADDRESS_CLAMP;
    s.MaxAnisotropy = 1;
    s.ComparisonFunc = settings.comparison ? D3D11_COMPARISON_LESS_EQUAL : D3D11_COMPARISON_NEVER;
    s.MaxLOD = settings.mips ? D3D11_FLOAT32_MAX : 0.0f;
    const HRESULT hr = device_->CreateSamplerState(&s, &cached);
    if (FAILED(hr)) {
      samplers_.erase(settings);
      return failed("CreateSamplerState", hr, desc.filter + " " + desc.mip_filter);
    }
  }
  state = cached.Get();
  return {};
}

std::string D3D11Device::constant_buffer(const ConstantBlock& block, ID3D11Buffer*& buffer) {
  ComPtr<ID3D11Buffer>& cached = constants_[{block.stage, block.slot, block.bytes.size()}];
  if (!cached) {
    D3D11_BUFFER_DESC desc{};
    desc.ByteWidth = static_cast<UINT>(block.bytes.size());
    desc.Usage = D3D11_USAGE_DEFAULT;
    desc.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
    const HRESULT hr = device_->CreateBuffer(&desc, nullptr, &cached);
    if (FAILED(hr)) {
      constants_.erase({block.stage, block.slot, block.bytes.size()});
      return failed("CreateBuffer", hr, "constant buffer b" + std::to_string(block.slot));
    }
  }
  buffer = cached.Get();
  return {};
}

std::string D3D11Device::draw(const Draw& d) {
  // Everything is found or made before any state is set: a refused draw draws nothing.
  D3D11_VIEWPORT viewport{};
  viewport.MaxDepth = 1.0f;
  ID3D11RenderTargetView* rtv = nullptr;
  if (d.colour) {
    Texture* t = nullptr;
    if (std::string error = find_level(*d.colour, d.colour_level, t); !error.empty()) return error;
    if (t->desc.usage != Usage::target) return texture_name(*d.colour) + " is not a target";
    viewport.Width = static_cast<float>(level_size(t->desc.width, d.colour_level));
    viewport.Height = static_cast<float>(level_size(t->desc.height, d.colour_level));
    if (std::string error = render_target(*t, *d.colour, d.colour_level, rtv); !error.empty()) {
      return error;
    }
  } else if (d.clear_colour) {
    return "clear_colour without a colour target";
  }
  ID3D11DepthStencilView* dsv = nullptr;
  if (d.depth) {
    Texture* t = find_id(textures_, *d.depth);
    if (!t || t->desc.usage != Usage::depth) return texture_name(*d.depth) + " is not a depth map";
    const auto width = static_cast<float>(t->desc.width);
    const auto height = static_cast<float>(t->desc.height);
    if (d.colour && (viewport.Width != width || viewport.Height != height)) {
      return "the colour target and depth " + texture_name(*d.depth) + " differ in size";
    }
    viewport.Width = width;
    viewport.Height = height;
    if (std::string error = depth_stencil(*t, *d.depth, dsv); !error.empty()) return error;
  } else if (d.clear_depth) {
    return "clear_depth without a depth map";
  }
  if (!rtv && !dsv) return "a draw needs a colour target or a depth map";

  Shader* vs = nullptr;
  Shader* ps = nullptr;
  if (std::string error = find_shader(d.vs, Stage::vertex, vs); !error.empty()) return error;
  if (std::string error = find_shader(d.ps, Stage::pixel, ps); !error.empty()) return error;
  Buffer* vertices = find_id(buffers_, d.vertices);
  if (!vertices) return "unknown buffer " + std::to_string(d.vertices);
  if (std::size_t{d.stride} * d.count > vertices->bytes) {
    return std::to_string(d.count) + " vertices of " + std::to_string(d.stride) +
           " bytes overrun buffer " + std::to_string(d.vertices);
  }
  ID3D11InputLayout* layout = nullptr;
  if (std::string error = input_layout(*vs, d.vs, d.inputs, layout); !error.empty()) return error;

  std::vector<ConstantBlock> blocks;
  if (std::string error =
          pack_blocks(d.members, D3D11_COMMONSHADER_CONSTANT_BUFFER_API_SLOT_COUNT, blocks);
      !error.empty()) {
    return error;
  }
  std::vector<ID3D11Buffer*> block_buffers(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (std::string error = constant_buffer(blocks[i], block_buffers[i]); !error.empty()) {
      return error;
    }
  }
  std::vector<std::pair<UINT, ID3D11ShaderResourceView*>> views;
  for (const TextureBind& bind : d.textures) {
    UINT slot = 0;
    if (std::string error =
            parse_register(bind.reg, 't', D3D11_COMMONSHADER_INPUT_RESOURCE_SLOT_COUNT, slot);
        !error.empty()) {
      return error;
    }
    Texture* t = find_id(textures_, bind.texture);
    if (!t) return "unknown " + texture_name(bind.texture);
    // The runtime would unbind one of the two, with only a debug-layer warning.
    if (bind.texture == d.colour || bind.texture == d.depth) {
      return texture_name(bind.texture) + " is read and drawn into by one draw";
    }
    ID3D11ShaderResourceView* view = nullptr;
    if (std::string error = resource_view(*t, bind.texture, bind.view_format, view);
        !error.empty()) {
      return error;
    }
    views.emplace_back(slot, view);
  }
  std::vector<std::pair<UINT, ID3D11SamplerState*>> samplers;
  for (const SamplerBind& bind : d.samplers) {
    UINT slot = 0;
    ID3D11SamplerState* state = nullptr;
    std::string error = parse_register(bind.reg, 's', D3D11_COMMONSHADER_SAMPLER_SLOT_COUNT, slot);
    if (error.empty()) error = sampler(bind.state, state);
    if (!error.empty()) return error + " (sampler " + bind.reg + ")";
    samplers.emplace_back(slot, state);
  }

  context_->OMSetRenderTargets(rtv ? 1 : 0, rtv ? &rtv : nullptr, dsv);
  context_->OMSetDepthStencilState(dsv ? depth_test_.Get() : no_depth_.Get(), 0);
  context_->OMSetBlendState(nullptr, nullptr, 0xffffffff);
  context_->RSSetState(rasterizer_.Get());
  context_->RSSetViewports(1, &viewport);
  if (d.clear_colour) context_->ClearRenderTargetView(rtv, d.clear_colour->data());
  if (d.clear_depth) context_->ClearDepthStencilView(dsv, D3D11_CLEAR_DEPTH, *d.clear_depth, 0);
  ID3D11Buffer* vertex_buffer = vertices->buffer.Get();
  const UINT offset = 0;
  context_->IASetInputLayout(layout);
  context_->IASetVertexBuffers(0, 1, &vertex_buffer, &d.stride, &offset);
  context_->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  context_->VSSetShader(vs->vertex.Get(), nullptr, 0);
  context_->PSSetShader(ps->pixel.Get(), nullptr, 0);
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    context_->UpdateSubresource(block_buffers[i], 0, nullptr, blocks[i].bytes.data(), 0, 0);
    if (blocks[i].stage == Stage::vertex) {
      context_->VSSetConstantBuffers(blocks[i].slot, 1, &block_buffers[i]);
    } else {
      context_->PSSetConstantBuffers(blocks[i].slot, 1, &block_buffers[i]);
    }
  }
  for (auto& [slot, view] : views) context_->PSSetShaderResources(slot, 1, &view);
  for (auto& [slot, state] : samplers) context_->PSSetSamplers(slot, 1, &state);
  context_->Draw(d.count, 0);

  // Unbound, this draw's textures and targets may swap roles in the next one.
  ID3D11ShaderResourceView* none = nullptr;
  for (const auto& bound : views) context_->PSSetShaderResources(bound.first, 1, &none);
  context_->OMSetRenderTargets(0, nullptr, nullptr);
  return {};
}

std::string D3D11Device::copy(int src, int src_level, int dst, int dst_level) {
  Texture* from = nullptr;
  Texture* to = nullptr;
  if (std::string error = find_level(src, src_level, from); !error.empty()) return error;
  if (std::string error = find_level(dst, dst_level, to); !error.empty()) return error;
  const std::string what = "copy from " + texture_name(src) + " to " + texture_name(dst);
  if (std::string error = check_copy(from->desc, src_level, to->desc, dst_level); !error.empty()) {
    return what + ": " + error;
  }
  if (src == dst && src_level == dst_level) return what + ": a level onto itself";
  if (to->desc.usage == Usage::depth && !depth_copies_) {
    return what + ": feature level 10_0 cannot copy into a depth texture";
  }
  // No box: the whole source level, at the destination's texel (0, 0).
  context_->CopySubresourceRegion(to->texture.Get(), dst_level, 0, 0, 0, from->texture.Get(),
                                  src_level, nullptr);
  return {};
}

std::vector<float> D3D11Device::read(int id, int level, std::string& error) {
  Texture* t = nullptr;
  if (error = find_level(id, level, t); !error.empty()) return {};
  ComPtr<ID3D11Texture2D> staging;
  error = make_staging(*t, level, D3D11_CPU_ACCESS_READ, staging, id);
  if (!error.empty()) return {};
  context_->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, t->texture.Get(), level, nullptr);
  D3D11_MAPPED_SUBRESOURCE mapped{};
  const HRESULT hr = context_->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped);
  if (FAILED(hr)) {
    error = failed("Map (staging)", hr, texture_name(id));
    return {};
  }
  std::vector<float> texels =
      read_rows(mapped.pData, mapped.RowPitch, level_size(t->desc.width, level) * t->format.bytes,
                level_size(t->desc.height, level));
  context_->Unmap(staging.Get(), 0);
  return texels;
}

void D3D11Device::release(int id) {
  textures_.erase(id);
  buffers_.erase(id);
  shaders_.erase(id);
}

}  // namespace

std::unique_ptr<Device> create_d3d11_device(bool feature_level_10, std::string& error) {
  const D3D_FEATURE_LEVEL level =
      feature_level_10 ? D3D_FEATURE_LEVEL_10_0 : D3D_FEATURE_LEVEL_11_0;
  const std::string level_name = feature_level_10 ? "10_0" : "11_0";
  ComPtr<ID3D11Device> device;
  ComPtr<ID3D11DeviceContext> context;
  const HRESULT hr = D3D11CreateDevice(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, &level, 1,
                                       D3D11_SDK_VERSION, &device, nullptr, &context);
  if (FAILED(hr)) {
    error = failed("D3D11CreateDevice", hr, "feature level " + level_name);
    return nullptr;
  }
  const std::string adapter = adapter_name(device.Get(), error);
  if (!error.empty()) return nullptr;
  auto result = std::make_unique<D3D11Device>(
      device, context, level, "Direct3D 11 (feature level " + level_name + ") on " + adapter);
  if (error = result->init(); !error.empty()) return nullptr;
  return result;
}

}  // namespace penumbra::d3dhost
