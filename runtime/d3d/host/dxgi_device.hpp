// Direct3D 10 and 11 behind device.hpp's Device, written once for both:
// DxgiDevice<Api> makes the resources on an Api::Device and draws on an
// Api::Context. `Api` is one API's traits struct (D3D10Api in
// d3d10_device.cpp, D3D11Api in d3d11_device.cpp), all static:
//   - the interfaces: Device, Context, Texture2D, Buffer, RenderTargetView,
//     DepthStencilView, ShaderResourceView, VertexShader, PixelShader,
//     InputLayout, SamplerState, RasterizerState, DepthStencilState;
//   - the descriptions: RasterizerDesc, DepthStencilOpDesc,
//     DepthStencilDesc, Texture2DDesc, SubresourceData, BufferDesc,
//     RenderTargetViewDesc, DepthStencilViewDesc, ShaderResourceViewDesc,
//     InputElementDesc, SamplerStateDesc, Viewport, Mapped;
//   - the constants, the API's own names in lower case without the prefix
//     (D3D10_USAGE_DEFAULT is usage_default), the slot counts as
//     constant_buffer_slots, resource_slots and sampler_slots, and
//     level_10_0, the name of the level that cannot copy into a depth map;
//   - the calls that differ between the two: create_shader(device, code,
//     shader) for either stage, set_shaders(context, vs, ps),
//     set_blend_state(context) (no blending), map(context, staging, type,
//     mapped) and unmap(context, staging).
#pragma once

#include <wrl/client.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "device.hpp"
#include "dxgi_names.hpp"

namespace penumbra::d3dhost {

template <typename Api>
class DxgiDevice final : public Device {
 public:
  // `depth_copies`: whether copies may write a depth-stencil resource
  // (feature level 10_1 and up).
  DxgiDevice(Microsoft::WRL::ComPtr<typename Api::Device> device,
             Microsoft::WRL::ComPtr<typename Api::Context> context, bool depth_copies,
             std::string description)
      : device_(std::move(device)),
        context_(std::move(context)),
        depth_copies_(depth_copies),
        description_(std::move(description)) {}

  // Makes the fixed draw state; empty on success.
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
  template <typename T>
  using ComPtr = Microsoft::WRL::ComPtr<T>;
  using Texture2D = typename Api::Texture2D;
  using RenderTargetView = typename Api::RenderTargetView;
  using DepthStencilView = typename Api::DepthStencilView;
  using ShaderResourceView = typename Api::ShaderResourceView;
  using InputLayout = typename Api::InputLayout;
  using SamplerState = typename Api::SamplerState;
  // A viewport's width and height: UINT on D3D10, FLOAT on D3D11.
  using Extent = decltype(typename Api::Viewport{}.Width);

  struct Texture {
    TextureDesc desc;
    DxgiFormat format;
    ComPtr<Texture2D> texture;
    // Views, each made when a draw first needs it.
    std::vector<ComPtr<RenderTargetView>> targets;  // per level
    ComPtr<DepthStencilView> depth;
    std::map<DXGI_FORMAT, ComPtr<ShaderResourceView>> views;
  };

  struct Buffer {
    ComPtr<typename Api::Buffer> buffer;
    UINT bytes = 0;
  };

  struct Shader {
    Stage stage = Stage::pixel;
    ComPtr<typename Api::VertexShader> vertex;
    ComPtr<typename Api::PixelShader> pixel;
    std::vector<unsigned char> code;  // a vertex shader's: input layouts are checked against it
    std::map<std::string, ComPtr<InputLayout>> layouts;  // by the draw's inputs
  };

  static std::string texture_name(int id) { return "texture " + std::to_string(id); }

  std::string make_texture(Texture& t, const typename Api::SubresourceData* data, int id);
  std::string make_staging(const Texture& t, int level, UINT cpu_access, ComPtr<Texture2D>& staging,
                           int id);
  // Copies level `level` of `t`'s layer `layer` to a staging texture, maps
  // it and calls use(data, row pitch) while mapped.
  template <typename Use>
  std::string with_staged(const Texture& t, int level, int layer, int id, Use use);
  // How far a staged D24 texel's depth lies from bit 0 (read_unorm_rows()).
  std::string d24_depth_shift(unsigned& shift);
  std::string find_level(int id, int level, Texture*& t);
  std::string find_shader(int id, Stage stage, Shader*& s);
  std::string render_target(Texture& t, int id, int level, RenderTargetView*& view);
  std::string depth_stencil(Texture& t, int id, DepthStencilView*& view);
  std::string resource_view(Texture& t, int id, const std::string& view_format,
                            ShaderResourceView*& view);
  std::string input_layout(Shader& vs, int id, const std::vector<InputElement>& inputs,
                           InputLayout*& layout);
  std::string sampler(const SamplerDesc& desc, SamplerState*& state);
  std::string constant_buffer(const ConstantBlock& block, typename Api::Buffer*& buffer);

  ComPtr<typename Api::Device> device_;
  ComPtr<typename Api::Context> context_;
  bool depth_copies_;
  std::string description_;
  ComPtr<typename Api::RasterizerState> rasterizer_;
  ComPtr<typename Api::DepthStencilState> depth_test_;
  ComPtr<typename Api::DepthStencilState> depth_greater_;  // reversed-Z maps
  ComPtr<typename Api::DepthStencilState> no_depth_;
  std::map<int, Texture> textures_;
  std::map<int, Buffer> buffers_;
  std::map<int, Shader> shaders_;
  std::map<SamplerSettings, ComPtr<SamplerState>> samplers_;
  std::map<std::tuple<Stage, UINT, std::size_t>, ComPtr<typename Api::Buffer>> constants_;
  std::optional<unsigned> d24_shift_;  // found by the first D24 read
};

template <typename Api>
std::string DxgiDevice<Api>::init() {
  typename Api::RasterizerDesc raster{};
  raster.FillMode = Api::fill_solid;
  raster.CullMode = Api::cull_none;
  raster.DepthClipEnable = TRUE;
  HRESULT hr = device_->CreateRasterizerState(&raster, &rasterizer_);
  if (FAILED(hr)) return failed("CreateRasterizerState", hr, "the draw state");
  // Stencil is off, but its operations must still be valid values.
  const typename Api::DepthStencilOpDesc keep = {Api::stencil_op_keep, Api::stencil_op_keep,
                                                 Api::stencil_op_keep, Api::comparison_always};
  typename Api::DepthStencilDesc depth{};
  depth.DepthEnable = TRUE;
  depth.DepthWriteMask = Api::depth_write_mask_all;
  depth.DepthFunc = Api::comparison_less;
  depth.StencilReadMask = Api::default_stencil_read_mask;
  depth.StencilWriteMask = Api::default_stencil_write_mask;
  depth.FrontFace = keep;
  depth.BackFace = keep;
  if (hr = device_->CreateDepthStencilState(&depth, &depth_test_); FAILED(hr)) {
    return failed("CreateDepthStencilState", hr, "depth test");
  }
  depth.DepthFunc = Api::comparison_greater;
  if (hr = device_->CreateDepthStencilState(&depth, &depth_greater_); FAILED(hr)) {
    return failed("CreateDepthStencilState", hr, "reversed depth test");
  }
  depth.DepthEnable = FALSE;
  depth.DepthWriteMask = Api::depth_write_mask_zero;
  if (hr = device_->CreateDepthStencilState(&depth, &no_depth_); FAILED(hr)) {
    return failed("CreateDepthStencilState", hr, "no depth");
  }
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::make_texture(Texture& t, const typename Api::SubresourceData* data,
                                          int id) {
  typename Api::Texture2DDesc desc{};
  desc.Width = static_cast<UINT>(t.desc.width);
  desc.Height = static_cast<UINT>(t.desc.height);
  desc.MipLevels = static_cast<UINT>(t.desc.levels);
  desc.ArraySize = static_cast<UINT>(std::max(1, t.desc.layers));
  desc.Format = t.format.format;
  desc.SampleDesc.Count = 1;
  desc.Usage = Api::usage_default;
  switch (t.desc.usage) {
    case Usage::target:
      desc.BindFlags = Api::bind_render_target | Api::bind_shader_resource;
      break;
    case Usage::depth:
      desc.BindFlags = Api::bind_depth_stencil | Api::bind_shader_resource;
      break;
    case Usage::input:
      desc.BindFlags = Api::bind_shader_resource;
      break;
  }
  t.targets.resize(desc.MipLevels);
  const HRESULT hr = device_->CreateTexture2D(&desc, data, &t.texture);
  return FAILED(hr) ? failed("CreateTexture2D", hr, texture_name(id)) : std::string();
}

// A one-level CPU copy of `t`'s level `level`, same format (typeless too).
template <typename Api>
std::string DxgiDevice<Api>::make_staging(const Texture& t, int level, UINT cpu_access,
                                          ComPtr<Texture2D>& staging, int id) {
  typename Api::Texture2DDesc desc{};
  desc.Width = level_size(t.desc.width, level);
  desc.Height = level_size(t.desc.height, level);
  desc.MipLevels = 1;
  desc.ArraySize = 1;
  desc.Format = t.format.format;
  desc.SampleDesc.Count = 1;
  desc.Usage = Api::usage_staging;
  desc.CPUAccessFlags = cpu_access;
  const HRESULT hr = device_->CreateTexture2D(&desc, nullptr, &staging);
  return FAILED(hr) ? failed("CreateTexture2D (staging)", hr, texture_name(id)) : std::string();
}

template <typename Api>
std::string DxgiDevice<Api>::find_level(int id, int level, Texture*& t) {
  t = find_id(textures_, id);
  if (!t) return "unknown " + texture_name(id);
  if (level < 0 || level >= t->desc.levels) {
    return "level " + std::to_string(level) + " of " + texture_name(id) + ", which has " +
           std::to_string(t->desc.levels);
  }
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::find_shader(int id, Stage stage, Shader*& s) {
  s = find_id(shaders_, id);
  const std::string name = "shader " + std::to_string(id);
  if (!s) return "unknown " + name;
  if (s->stage != stage) return name + (stage == Stage::vertex ? " is no vs" : " is no ps");
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::create_texture(int id, const TextureDesc& desc) {
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

template <typename Api>
std::string DxgiDevice<Api>::upload(int id, int level, const std::vector<float>& texels) {
  Texture* t = nullptr;
  if (std::string error = find_level(id, level, t); !error.empty()) return error;
  if (t->format.unorm_bits) {
    return texture_name(id) + " holds unorm depth: it is drawn, not uploaded as floats";
  }
  const UINT row = level_size(t->desc.width, level) * t->format.bytes;
  const UINT rows = level_size(t->desc.height, level);
  const auto layers = static_cast<UINT>(std::max(1, t->desc.layers));
  const std::size_t layer_floats = std::size_t{row} / sizeof(float) * rows;
  if (texels.size() != layer_floats * layers) {
    return "level " + std::to_string(level) + " of " + texture_name(id) + " takes " +
           std::to_string(layer_floats * layers) + " floats, not " + std::to_string(texels.size());
  }
  // Subresource level + layer * levels: each layer's level.
  const auto subresource = [&](UINT layer) {
    return static_cast<UINT>(level) + layer * static_cast<UINT>(t->desc.levels);
  };
  if (t->desc.usage != Usage::depth) {
    for (UINT layer = 0; layer < layers; ++layer) {
      context_->UpdateSubresource(t->texture.Get(), subresource(layer), nullptr,
                                  texels.data() + layer * layer_floats, row, 0);
    }
    return {};
  }
  // UpdateSubresource may not write a depth-stencil resource; a copy from a
  // staging texture may from feature level 10_1 on. Below that nothing may
  // write one but the pipeline and its creation, so the map is made anew
  // with the texels as its initial data (it has one level).
  if (!depth_copies_) {
    std::vector<typename Api::SubresourceData> data;
    for (UINT layer = 0; layer < layers; ++layer) {
      data.push_back({texels.data() + layer * layer_floats, row, 0});
    }
    Texture fresh;
    fresh.desc = t->desc;
    fresh.format = t->format;
    if (std::string error = make_texture(fresh, data.data(), id); !error.empty()) return error;
    *t = std::move(fresh);
    return {};
  }
  ComPtr<Texture2D> staging;
  if (std::string error = make_staging(*t, level, Api::cpu_access_write, staging, id);
      !error.empty()) {
    return error;
  }
  for (UINT layer = 0; layer < layers; ++layer) {
    typename Api::Mapped mapped{};
    const HRESULT hr = Api::map(context_.Get(), staging.Get(), Api::map_write, mapped);
    if (FAILED(hr)) return failed("Map (staging)", hr, texture_name(id));
    write_rows(std::span(texels).subspan(layer * layer_floats, layer_floats), row, mapped.pData,
               mapped.RowPitch);
    Api::unmap(context_.Get(), staging.Get());
    // A depth-stencil copy takes the whole subresource: no box.
    context_->CopySubresourceRegion(t->texture.Get(), subresource(layer), 0, 0, 0, staging.Get(), 0,
                                    nullptr);
  }
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::create_buffer(int id, const std::vector<float>& data) {
  release(id);
  if (data.empty()) return "buffer " + std::to_string(id) + " is empty";
  Buffer b;
  b.bytes = static_cast<UINT>(data.size() * sizeof(float));
  typename Api::BufferDesc desc{};
  desc.ByteWidth = b.bytes;
  desc.Usage = Api::usage_immutable;
  desc.BindFlags = Api::bind_vertex_buffer;
  const typename Api::SubresourceData init{data.data(), 0, 0};
  const HRESULT hr = device_->CreateBuffer(&desc, &init, &b.buffer);
  if (FAILED(hr)) return failed("CreateBuffer", hr, "buffer " + std::to_string(id));
  buffers_.emplace(id, std::move(b));
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::create_shader(int id, Stage stage,
                                           const std::vector<unsigned char>& code) {
  release(id);
  const std::string name = "shader " + std::to_string(id);
  if (code.empty()) return name + " is empty";
  Shader s;
  s.stage = stage;
  if (stage == Stage::vertex) {
    const HRESULT hr = Api::create_shader(device_.Get(), code, s.vertex);
    if (FAILED(hr)) return failed("CreateVertexShader", hr, name);
    s.code = code;
  } else {
    const HRESULT hr = Api::create_shader(device_.Get(), code, s.pixel);
    if (FAILED(hr)) return failed("CreatePixelShader", hr, name);
  }
  shaders_.emplace(id, std::move(s));
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::render_target(Texture& t, int id, int level, RenderTargetView*& view) {
  ComPtr<RenderTargetView>& cached = t.targets[static_cast<std::size_t>(level)];
  if (!cached) {
    typename Api::RenderTargetViewDesc desc{};
    desc.Format = t.format.format;
    desc.ViewDimension = Api::rtv_dimension_texture2d;
    desc.Texture2D.MipSlice = static_cast<UINT>(level);
    const HRESULT hr = device_->CreateRenderTargetView(t.texture.Get(), &desc, &cached);
    if (FAILED(hr)) return failed("CreateRenderTargetView", hr, texture_name(id));
  }
  view = cached.Get();
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::depth_stencil(Texture& t, int id, DepthStencilView*& view) {
  if (!t.depth) {
    typename Api::DepthStencilViewDesc desc{};
    desc.Format = t.format.depth_view;
    desc.ViewDimension = Api::dsv_dimension_texture2d;
    const HRESULT hr = device_->CreateDepthStencilView(t.texture.Get(), &desc, &t.depth);
    if (FAILED(hr)) return failed("CreateDepthStencilView", hr, texture_name(id));
  }
  view = t.depth.Get();
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::resource_view(Texture& t, int id, const std::string& view_format,
                                           ShaderResourceView*& view) {
  DxgiFormat format = t.format;
  if (!view_format.empty()) {
    if (std::string error = parse_format(view_format, FormatUse::view, format); !error.empty()) {
      return error + " (" + texture_name(id) + ")";
    }
  } else if (t.desc.usage == Usage::depth) {
    return texture_name(id) + " is typeless: its binding needs a view format";
  }
  ComPtr<ShaderResourceView>& cached = t.views[format.format];
  if (!cached) {
    typename Api::ShaderResourceViewDesc desc{};
    desc.Format = format.format;
    if (t.desc.layers > 0) {
      desc.ViewDimension = Api::srv_dimension_texture2darray;
      desc.Texture2DArray.MipLevels = static_cast<UINT>(t.desc.levels);
      desc.Texture2DArray.ArraySize = static_cast<UINT>(t.desc.layers);
    } else {
      desc.ViewDimension = Api::srv_dimension_texture2d;
      desc.Texture2D.MipLevels = static_cast<UINT>(t.desc.levels);
    }
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

template <typename Api>
std::string DxgiDevice<Api>::input_layout(Shader& vs, int id,
                                          const std::vector<InputElement>& inputs,
                                          InputLayout*& layout) {
  std::string key;
  for (const InputElement& input : inputs) {
    key += input.semantic + " " + input.format + " " + std::to_string(input.offset) + ";";
  }
  ComPtr<InputLayout>& cached = vs.layouts[key];
  if (!cached) {
    std::vector<std::string> names(inputs.size());  // SemanticName points into these
    std::vector<typename Api::InputElementDesc> elements(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      typename Api::InputElementDesc& e = elements[i];
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
      e.InputSlotClass = Api::input_per_vertex_data;
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

template <typename Api>
std::string DxgiDevice<Api>::sampler(const SamplerDesc& desc, SamplerState*& state) {
  SamplerSettings settings;
  if (std::string error = parse_sampler(desc, settings); !error.empty()) return error;
  ComPtr<SamplerState>& cached = samplers_[settings];
  if (!cached) {
    typename Api::SamplerStateDesc s{};
    if (settings.comparison) {
      s.Filter = settings.linear ? Api::filter_comparison_min_mag_linear_mip_point
                                 : Api::filter_comparison_min_mag_mip_point;
    } else {
      s.Filter =
          settings.linear ? Api::filter_min_mag_linear_mip_point : Api::filter_min_mag_mip_point;
    }
    s.AddressU = s.AddressV = s.AddressW = Api::texture_address_clamp;
    s.MaxAnisotropy = 1;
    s.ComparisonFunc = !settings.comparison     ? Api::comparison_never
                       : settings.greater_equal ? Api::comparison_greater_equal
                                                : Api::comparison_less_equal;
    s.MaxLOD = settings.mips ? Api::float32_max : 0.0f;
    const HRESULT hr = device_->CreateSamplerState(&s, &cached);
    if (FAILED(hr)) {
      samplers_.erase(settings);
      return failed("CreateSamplerState", hr, desc.filter + " " + desc.mip_filter);
    }
  }
  state = cached.Get();
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::constant_buffer(const ConstantBlock& block,
                                             typename Api::Buffer*& buffer) {
  ComPtr<typename Api::Buffer>& cached = constants_[{block.stage, block.slot, block.bytes.size()}];
  if (!cached) {
    typename Api::BufferDesc desc{};
    desc.ByteWidth = static_cast<UINT>(block.bytes.size());
    desc.Usage = Api::usage_default;
    desc.BindFlags = Api::bind_constant_buffer;
    const HRESULT hr = device_->CreateBuffer(&desc, nullptr, &cached);
    if (FAILED(hr)) {
      constants_.erase({block.stage, block.slot, block.bytes.size()});
      return failed("CreateBuffer", hr, "constant buffer b" + std::to_string(block.slot));
    }
  }
  buffer = cached.Get();
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::draw(const Draw& d) {
  // Everything is found or made before any state is set: a refused draw draws nothing.
  typename Api::Viewport viewport{};
  viewport.MaxDepth = 1.0f;
  RenderTargetView* rtv = nullptr;
  if (d.colour) {
    Texture* t = nullptr;
    if (std::string error = find_level(*d.colour, d.colour_level, t); !error.empty()) return error;
    if (t->desc.usage != Usage::target) return texture_name(*d.colour) + " is not a target";
    viewport.Width = static_cast<Extent>(level_size(t->desc.width, d.colour_level));
    viewport.Height = static_cast<Extent>(level_size(t->desc.height, d.colour_level));
    if (std::string error = render_target(*t, *d.colour, d.colour_level, rtv); !error.empty()) {
      return error;
    }
  } else if (d.clear_colour) {
    return "clear_colour without a colour target";
  }
  DepthStencilView* dsv = nullptr;
  if (d.depth) {
    Texture* t = find_id(textures_, *d.depth);
    if (!t || t->desc.usage != Usage::depth) return texture_name(*d.depth) + " is not a depth map";
    const auto width = static_cast<Extent>(t->desc.width);
    const auto height = static_cast<Extent>(t->desc.height);
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
  InputLayout* layout = nullptr;
  if (std::string error = input_layout(*vs, d.vs, d.inputs, layout); !error.empty()) return error;

  std::vector<ConstantBlock> blocks;
  if (std::string error = pack_blocks(d.members, Api::constant_buffer_slots, blocks);
      !error.empty()) {
    return error;
  }
  std::vector<typename Api::Buffer*> block_buffers(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (std::string error = constant_buffer(blocks[i], block_buffers[i]); !error.empty()) {
      return error;
    }
  }
  std::vector<std::pair<UINT, ShaderResourceView*>> views;
  for (const TextureBind& bind : d.textures) {
    UINT slot = 0;
    if (std::string error = parse_register(bind.reg, 't', Api::resource_slots, slot);
        !error.empty()) {
      return error;
    }
    Texture* t = find_id(textures_, bind.texture);
    if (!t) return "unknown " + texture_name(bind.texture);
    // The runtime would unbind one of the two, with only a debug-layer warning.
    if (bind.texture == d.colour || bind.texture == d.depth) {
      return texture_name(bind.texture) + " is read and drawn into by one draw";
    }
    ShaderResourceView* view = nullptr;
    if (std::string error = resource_view(*t, bind.texture, bind.view_format, view);
        !error.empty()) {
      return error;
    }
    views.emplace_back(slot, view);
  }
  std::vector<std::pair<UINT, SamplerState*>> samplers;
  for (const SamplerBind& bind : d.samplers) {
    UINT slot = 0;
    SamplerState* state = nullptr;
    std::string error = parse_register(bind.reg, 's', Api::sampler_slots, slot);
    if (error.empty()) error = sampler(bind.state, state);
    if (!error.empty()) return error + " (sampler " + bind.reg + ")";
    samplers.emplace_back(slot, state);
  }

  context_->OMSetRenderTargets(rtv ? 1 : 0, rtv ? &rtv : nullptr, dsv);
  context_->OMSetDepthStencilState(!dsv              ? no_depth_.Get()
                                   : d.depth_greater ? depth_greater_.Get()
                                                     : depth_test_.Get(),
                                   0);
  Api::set_blend_state(context_.Get());
  context_->RSSetState(rasterizer_.Get());
  context_->RSSetViewports(1, &viewport);
  if (d.clear_colour) context_->ClearRenderTargetView(rtv, d.clear_colour->data());
  if (d.clear_depth) context_->ClearDepthStencilView(dsv, Api::clear_depth, *d.clear_depth, 0);
  typename Api::Buffer* vertex_buffer = vertices->buffer.Get();
  const UINT offset = 0;
  context_->IASetInputLayout(layout);
  context_->IASetVertexBuffers(0, 1, &vertex_buffer, &d.stride, &offset);
  context_->IASetPrimitiveTopology(Api::primitive_topology_trianglelist);
  Api::set_shaders(context_.Get(), vs->vertex.Get(), ps->pixel.Get());
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
  ShaderResourceView* none = nullptr;
  for (const auto& bound : views) context_->PSSetShaderResources(bound.first, 1, &none);
  context_->OMSetRenderTargets(0, nullptr, nullptr);
  return {};
}

template <typename Api>
std::string DxgiDevice<Api>::copy(int src, int src_level, int dst, int dst_level) {
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
    return what + ": " + Api::level_10_0 + " cannot copy into a depth texture";
  }
  // No box: the whole source level, at the destination's texel (0, 0).
  context_->CopySubresourceRegion(to->texture.Get(), dst_level, 0, 0, 0, from->texture.Get(),
                                  src_level, nullptr);
  return {};
}

template <typename Api>
template <typename Use>
std::string DxgiDevice<Api>::with_staged(const Texture& t, int level, int layer, int id, Use use) {
  ComPtr<Texture2D> staging;
  if (std::string error = make_staging(t, level, Api::cpu_access_read, staging, id);
      !error.empty()) {
    return error;
  }
  const UINT subresource = static_cast<UINT>(level + layer * t.desc.levels);
  context_->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, t.texture.Get(), subresource, nullptr);
  typename Api::Mapped mapped{};
  const HRESULT hr = Api::map(context_.Get(), staging.Get(), Api::map_read, mapped);
  if (FAILED(hr)) return failed("Map (staging)", hr, texture_name(id));
  use(mapped.pData, mapped.RowPitch);
  Api::unmap(context_.Get(), staging.Get());
  return {};
}

// Direct3D stages an R24G8 texel with its depth in the low 24 bits; Wine's
// d3d10 and d3d11 stage it as OpenGL packs D24S8, depth in the high 24. So
// the first D24 read clears a 1x1 probe to depth 0.5 and looks.
template <typename Api>
std::string DxgiDevice<Api>::d24_depth_shift(unsigned& shift) {
  if (!d24_shift_) {
    constexpr int kProbe = -1;  // an id no job uses
    Texture probe;
    probe.desc = {"DXGI_FORMAT_R24G8_TYPELESS", 1, 1, 1, Usage::depth};
    DepthStencilView* view = nullptr;
    std::string error = check_texture(probe.desc, probe.format);
    if (error.empty()) error = make_texture(probe, nullptr, kProbe);
    if (error.empty()) error = depth_stencil(probe, kProbe, view);
    std::uint32_t texel = 0;
    if (error.empty()) {
      context_->ClearDepthStencilView(view, Api::clear_depth, 0.5f, 0);
      error = with_staged(probe, 0, 0, kProbe,
                          [&](const void* data, UINT) { std::memcpy(&texel, data, sizeof texel); });
    }
    if (!error.empty()) return error + " (the D24 layout probe)";
    // 0.5 is code 0x7FFFFF or 0x800000, whichever the device rounds to.
    const auto half = [](std::uint32_t code) { return code == 0x7FFFFF || code == 0x800000; };
    if (half(texel & 0xFFFFFF)) {
      d24_shift_ = 0;
    } else if (half(texel >> 8)) {
      d24_shift_ = 8;
    } else {
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%08X", static_cast<unsigned>(texel));
      return std::string("a D24 texel cleared to depth 0.5 staged as ") + hex +
             ", with the depth in neither the low nor the high 24 bits";
    }
  }
  shift = *d24_shift_;
  return {};
}

template <typename Api>
std::vector<float> DxgiDevice<Api>::read(int id, int level, std::string& error) {
  Texture* t = nullptr;
  if (error = find_level(id, level, t); !error.empty()) return {};
  unsigned shift = 0;
  if (t->format.unorm_bits == 24 && !(error = d24_depth_shift(shift)).empty()) return {};
  const UINT width = level_size(t->desc.width, level);
  const UINT rows = level_size(t->desc.height, level);
  std::vector<float> texels;
  // An array's layers one after another, as upload() takes them.
  for (int layer = 0; layer < std::max(1, t->desc.layers) && error.empty(); ++layer) {
    error = with_staged(*t, level, layer, id, [&](const void* data, UINT pitch) {
      const std::vector<float> rows_read =
          t->format.unorm_bits ? read_unorm_rows(data, pitch, width, rows, t->format, shift)
                               : read_rows(data, pitch, width * t->format.bytes, rows);
      texels.insert(texels.end(), rows_read.begin(), rows_read.end());
    });
  }
  return texels;
}

template <typename Api>
void DxgiDevice<Api>::release(int id) {
  textures_.erase(id);
  buffers_.erase(id);
  shaders_.erase(id);
}

}  // namespace penumbra::d3dhost
