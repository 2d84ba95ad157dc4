// Direct3D 11 behind device.hpp's Device (docs/engines/d3d11.md): the
// hardware driver at feature level 11_0, or 10_0 for hlsl_dx10's shaders;
// resources on the device, every draw on the immediate context.
#include <d3d11.h>
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

// dxgi_device.hpp's Api for Direct3D 11: draws go to the immediate context.
struct D3D11Api {
  using Device = ID3D11Device;
  using Context = ID3D11DeviceContext;
  using Texture2D = ID3D11Texture2D;
  using Buffer = ID3D11Buffer;
  using RenderTargetView = ID3D11RenderTargetView;
  using DepthStencilView = ID3D11DepthStencilView;
  using ShaderResourceView = ID3D11ShaderResourceView;
  using VertexShader = ID3D11VertexShader;
  using PixelShader = ID3D11PixelShader;
  using InputLayout = ID3D11InputLayout;
  using SamplerState = ID3D11SamplerState;
  using RasterizerState = ID3D11RasterizerState;
  using DepthStencilState = ID3D11DepthStencilState;

  using RasterizerDesc = D3D11_RASTERIZER_DESC;
  using DepthStencilOpDesc = D3D11_DEPTH_STENCILOP_DESC;
  using DepthStencilDesc = D3D11_DEPTH_STENCIL_DESC;
  using Texture2DDesc = D3D11_TEXTURE2D_DESC;
  using SubresourceData = D3D11_SUBRESOURCE_DATA;
  using BufferDesc = D3D11_BUFFER_DESC;
  using RenderTargetViewDesc = D3D11_RENDER_TARGET_VIEW_DESC;
  using DepthStencilViewDesc = D3D11_DEPTH_STENCIL_VIEW_DESC;
  using ShaderResourceViewDesc = D3D11_SHADER_RESOURCE_VIEW_DESC;
  using InputElementDesc = D3D11_INPUT_ELEMENT_DESC;
  using SamplerStateDesc = D3D11_SAMPLER_DESC;
  using Viewport = D3D11_VIEWPORT;
  using Mapped = D3D11_MAPPED_SUBRESOURCE;

  static constexpr auto fill_solid = D3D11_FILL_SOLID;
  static constexpr auto cull_none = D3D11_CULL_NONE;
  static constexpr auto stencil_op_keep = D3D11_STENCIL_OP_KEEP;
  static constexpr auto comparison_always = D3D11_COMPARISON_ALWAYS;
  static constexpr auto comparison_less = D3D11_COMPARISON_LESS;
  static constexpr auto comparison_less_equal = D3D11_COMPARISON_LESS_EQUAL;
  static constexpr auto comparison_greater = D3D11_COMPARISON_GREATER;
  static constexpr auto comparison_greater_equal = D3D11_COMPARISON_GREATER_EQUAL;
  static constexpr auto comparison_never = D3D11_COMPARISON_NEVER;
  static constexpr auto depth_write_mask_all = D3D11_DEPTH_WRITE_MASK_ALL;
  static constexpr auto depth_write_mask_zero = D3D11_DEPTH_WRITE_MASK_ZERO;
  static constexpr auto default_stencil_read_mask = D3D11_DEFAULT_STENCIL_READ_MASK;
  static constexpr auto default_stencil_write_mask = D3D11_DEFAULT_STENCIL_WRITE_MASK;
  static constexpr auto usage_default = D3D11_USAGE_DEFAULT;
  static constexpr auto usage_immutable = D3D11_USAGE_IMMUTABLE;
  static constexpr auto usage_staging = D3D11_USAGE_STAGING;
  static constexpr auto bind_render_target = D3D11_BIND_RENDER_TARGET;
  static constexpr auto bind_depth_stencil = D3D11_BIND_DEPTH_STENCIL;
  static constexpr auto bind_shader_resource = D3D11_BIND_SHADER_RESOURCE;
  static constexpr auto bind_vertex_buffer = D3D11_BIND_VERTEX_BUFFER;
  static constexpr auto bind_constant_buffer = D3D11_BIND_CONSTANT_BUFFER;
  static constexpr auto cpu_access_read = D3D11_CPU_ACCESS_READ;
  static constexpr auto cpu_access_write = D3D11_CPU_ACCESS_WRITE;
  static constexpr auto map_read = D3D11_MAP_READ;
  static constexpr auto map_write = D3D11_MAP_WRITE;
  static constexpr auto rtv_dimension_texture2d = D3D11_RTV_DIMENSION_TEXTURE2D;
  static constexpr auto dsv_dimension_texture2d = D3D11_DSV_DIMENSION_TEXTURE2D;
  static constexpr auto srv_dimension_texture2d = D3D11_SRV_DIMENSION_TEXTURE2D;
  static constexpr auto srv_dimension_texture2darray = D3D11_SRV_DIMENSION_TEXTURE2DARRAY;
  static constexpr auto input_per_vertex_data = D3D11_INPUT_PER_VERTEX_DATA;
  static constexpr auto filter_min_mag_mip_point = D3D11_FILTER_MIN_MAG_MIP_POINT;
  static constexpr auto filter_min_mag_linear_mip_point = D3D11_FILTER_MIN_MAG_LINEAR_MIP_POINT;
  static constexpr auto filter_comparison_min_mag_mip_point =
      D3D11_FILTER_COMPARISON_MIN_MAG_MIP_POINT;
  static constexpr auto filter_comparison_min_mag_linear_mip_point =
      D3D11_FILTER_COMPARISON_MIN_MAG_LINEAR_MIP_POINT;
  static constexpr auto texture_address_clamp = D3D11_TEXTURE_ADDRESS_CLAMP;
  static constexpr auto float32_max = D3D11_FLOAT32_MAX;
  static constexpr auto clear_depth = D3D11_CLEAR_DEPTH;
  static constexpr auto primitive_topology_trianglelist = D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST;
  static constexpr UINT constant_buffer_slots = D3D11_COMMONSHADER_CONSTANT_BUFFER_API_SLOT_COUNT;
  static constexpr UINT resource_slots = D3D11_COMMONSHADER_INPUT_RESOURCE_SLOT_COUNT;
  static constexpr UINT sampler_slots = D3D11_COMMONSHADER_SAMPLER_SLOT_COUNT;
  static constexpr const char* level_10_0 = "feature level 10_0";

  static HRESULT create_shader(Device* device, const std::vector<unsigned char>& code,
                               ComPtr<VertexShader>& shader) {
    return device->CreateVertexShader(code.data(), code.size(), nullptr, &shader);
  }
  static HRESULT create_shader(Device* device, const std::vector<unsigned char>& code,
                               ComPtr<PixelShader>& shader) {
    return device->CreatePixelShader(code.data(), code.size(), nullptr, &shader);
  }
  static void set_shaders(Context* context, VertexShader* vs, PixelShader* ps) {
    context->VSSetShader(vs, nullptr, 0);
    context->PSSetShader(ps, nullptr, 0);
  }
  static void set_blend_state(Context* context) {
    context->OMSetBlendState(nullptr, nullptr, 0xffffffff);
  }
  static HRESULT map(Context* context, Texture2D* staging, D3D11_MAP type, Mapped& mapped) {
    return context->Map(staging, 0, type, 0, &mapped);
  }
  static void unmap(Context* context, Texture2D* staging) { context->Unmap(staging, 0); }
};

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
  // Copies into a depth-stencil resource need feature level 10_1
  // (ID3D11DeviceContext::CopyResource's remarks).
  auto result = std::make_unique<DxgiDevice<D3D11Api>>(
      device, context, level >= D3D_FEATURE_LEVEL_10_1,
      "Direct3D 11 (feature level " + level_name + ") on " + adapter);
  if (error = result->init(); !error.empty()) return nullptr;
  return result;
}

}  // namespace penumbra::d3dhost
