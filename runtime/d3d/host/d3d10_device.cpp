// Direct3D 10 behind device.hpp's Device (docs/engines/d3d10.md): the
// hardware driver's ID3D10Device, which makes the resources and draws.
#include <d3d10.h>
#include <wrl/client.h>

#include <memory>
#include <string>
#include <vector>

#include "device.hpp"
#include "dxgi_device.hpp"
#include "dxgi_names.hpp"

namespace penumbra::d3dhost {
namespace {

using Microsoft::WRL::ComPtr;

// dxgi_device.hpp's Api for Direct3D 10, where the device is its own context.
struct D3D10Api {
  using Device = ID3D10Device;
  using Context = ID3D10Device;
  using Texture2D = ID3D10Texture2D;
  using Buffer = ID3D10Buffer;
  using RenderTargetView = ID3D10RenderTargetView;
  using DepthStencilView = ID3D10DepthStencilView;
  using ShaderResourceView = ID3D10ShaderResourceView;
  using VertexShader = ID3D10VertexShader;
  using PixelShader = ID3D10PixelShader;
  using InputLayout = ID3D10InputLayout;
  using SamplerState = ID3D10SamplerState;
  using RasterizerState = ID3D10RasterizerState;
  using DepthStencilState = ID3D10DepthStencilState;

  using RasterizerDesc = D3D10_RASTERIZER_DESC;
  using DepthStencilOpDesc = D3D10_DEPTH_STENCILOP_DESC;
  using DepthStencilDesc = D3D10_DEPTH_STENCIL_DESC;
  using Texture2DDesc = D3D10_TEXTURE2D_DESC;
  using SubresourceData = D3D10_SUBRESOURCE_DATA;
  using BufferDesc = D3D10_BUFFER_DESC;
  using RenderTargetViewDesc = D3D10_RENDER_TARGET_VIEW_DESC;
  using DepthStencilViewDesc = D3D10_DEPTH_STENCIL_VIEW_DESC;
  using ShaderResourceViewDesc = D3D10_SHADER_RESOURCE_VIEW_DESC;
  using InputElementDesc = D3D10_INPUT_ELEMENT_DESC;
  using SamplerStateDesc = D3D10_SAMPLER_DESC;
  using Viewport = D3D10_VIEWPORT;
  using Mapped = D3D10_MAPPED_TEXTURE2D;

  static constexpr auto fill_solid = D3D10_FILL_SOLID;
  static constexpr auto cull_none = D3D10_CULL_NONE;
  static constexpr auto stencil_op_keep = D3D10_STENCIL_OP_KEEP;
  static constexpr auto comparison_always = D3D10_COMPARISON_ALWAYS;
  static constexpr auto comparison_less = D3D10_COMPARISON_LESS;
  static constexpr auto comparison_less_equal = D3D10_COMPARISON_LESS_EQUAL;
  static constexpr auto comparison_greater = D3D10_COMPARISON_GREATER;
  static constexpr auto comparison_greater_equal = D3D10_COMPARISON_GREATER_EQUAL;
  static constexpr auto comparison_never = D3D10_COMPARISON_NEVER;
  static constexpr auto depth_write_mask_all = D3D10_DEPTH_WRITE_MASK_ALL;
  static constexpr auto depth_write_mask_zero = D3D10_DEPTH_WRITE_MASK_ZERO;
  static constexpr auto default_stencil_read_mask = D3D10_DEFAULT_STENCIL_READ_MASK;
  static constexpr auto default_stencil_write_mask = D3D10_DEFAULT_STENCIL_WRITE_MASK;
  static constexpr auto usage_default = D3D10_USAGE_DEFAULT;
  static constexpr auto usage_immutable = D3D10_USAGE_IMMUTABLE;
  static constexpr auto usage_staging = D3D10_USAGE_STAGING;
  static constexpr auto bind_render_target = D3D10_BIND_RENDER_TARGET;
  static constexpr auto bind_depth_stencil = D3D10_BIND_DEPTH_STENCIL;
  static constexpr auto bind_shader_resource = D3D10_BIND_SHADER_RESOURCE;
  static constexpr auto bind_vertex_buffer = D3D10_BIND_VERTEX_BUFFER;
  static constexpr auto bind_constant_buffer = D3D10_BIND_CONSTANT_BUFFER;
  static constexpr auto cpu_access_read = D3D10_CPU_ACCESS_READ;
  static constexpr auto cpu_access_write = D3D10_CPU_ACCESS_WRITE;
  static constexpr auto map_read = D3D10_MAP_READ;
  static constexpr auto map_write = D3D10_MAP_WRITE;
  static constexpr auto rtv_dimension_texture2d = D3D10_RTV_DIMENSION_TEXTURE2D;
  static constexpr auto dsv_dimension_texture2d = D3D10_DSV_DIMENSION_TEXTURE2D;
  static constexpr auto srv_dimension_texture2d = D3D10_SRV_DIMENSION_TEXTURE2D;
  static constexpr auto srv_dimension_texture2darray = D3D10_SRV_DIMENSION_TEXTURE2DARRAY;
  static constexpr auto input_per_vertex_data = D3D10_INPUT_PER_VERTEX_DATA;
  static constexpr auto filter_min_mag_mip_point = D3D10_FILTER_MIN_MAG_MIP_POINT;
  static constexpr auto filter_min_mag_linear_mip_point = D3D10_FILTER_MIN_MAG_LINEAR_MIP_POINT;
  static constexpr auto filter_comparison_min_mag_mip_point =
      D3D10_FILTER_COMPARISON_MIN_MAG_MIP_POINT;
  static constexpr auto filter_comparison_min_mag_linear_mip_point =
      D3D10_FILTER_COMPARISON_MIN_MAG_LINEAR_MIP_POINT;
  static constexpr auto texture_address_clamp = D3D10_TEXTURE_ADDRESS_CLAMP;
  static constexpr auto float32_max = static_cast<FLOAT>(D3D10_FLOAT32_MAX);
  static constexpr auto clear_depth = D3D10_CLEAR_DEPTH;
  static constexpr auto primitive_topology_trianglelist = D3D10_PRIMITIVE_TOPOLOGY_TRIANGLELIST;
  static constexpr UINT constant_buffer_slots = D3D10_COMMONSHADER_CONSTANT_BUFFER_API_SLOT_COUNT;
  static constexpr UINT resource_slots = D3D10_COMMONSHADER_INPUT_RESOURCE_SLOT_COUNT;
  static constexpr UINT sampler_slots = D3D10_COMMONSHADER_SAMPLER_SLOT_COUNT;
  static constexpr const char* level_10_0 = "Direct3D 10.0";

  static HRESULT create_shader(Device* device, const std::vector<unsigned char>& code,
                               ComPtr<VertexShader>& shader) {
    return device->CreateVertexShader(code.data(), code.size(), &shader);
  }
  static HRESULT create_shader(Device* device, const std::vector<unsigned char>& code,
                               ComPtr<PixelShader>& shader) {
    return device->CreatePixelShader(code.data(), code.size(), &shader);
  }
  static void set_shaders(Context* context, VertexShader* vs, PixelShader* ps) {
    context->VSSetShader(vs);
    context->PSSetShader(ps);
  }
  static void set_blend_state(Context* context) {
    const FLOAT blend_factor[4] = {1.0f, 1.0f, 1.0f, 1.0f};  // unused: no blending
    context->OMSetBlendState(nullptr, blend_factor, 0xffffffff);
  }
  // A Direct3D 10 texture maps itself.
  static HRESULT map(Context*, Texture2D* staging, D3D10_MAP type, Mapped& mapped) {
    return staging->Map(0, type, 0, &mapped);
  }
  static void unmap(Context*, Texture2D* staging) { staging->Unmap(0); }
};

}  // namespace

std::unique_ptr<Device> create_d3d10_device(std::string& error) {
  ComPtr<ID3D10Device> device;
  const HRESULT hr = D3D10CreateDevice(nullptr, D3D10_DRIVER_TYPE_HARDWARE, nullptr, 0,
                                       D3D10_SDK_VERSION, &device);
  if (FAILED(hr)) {
    error = failed("D3D10CreateDevice", hr, "the hardware driver");
    return nullptr;
  }
  const std::string adapter = adapter_name(device.Get(), error);
  if (!error.empty()) return nullptr;
  // Direct3D 10.0 lets neither UpdateSubresource nor a copy write a
  // depth-stencil resource (10.1 lets copies).
  auto result =
      std::make_unique<DxgiDevice<D3D10Api>>(device, device, false, "Direct3D 10 on " + adapter);
  if (error = result->init(); !error.empty()) return nullptr;
  return result;
}

}  // namespace penumbra::d3dhost
