#include "dxgi_names.hpp"

#include <dxgi.h>
#include <wrl/client.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace penumbra::d3dhost {
namespace {

struct FormatName {
  const char* name;
  DxgiFormat format;
  bool texture, view, vertex;  // the uses that accept it
};

// The reflection's formats (docs/shader-interface.md, "Formats"): R32G32B32
// is a vertex format only (no render target needs it). The typeless ones
// are a shadow map's resource formats only (views name a typed format):
// R32_TYPELESS the library's D32 map, R24G8 and R16 an engine's D24 and D16
// maps, read through their unorm views.
constexpr FormatName kFormats[] = {
    {"DXGI_FORMAT_R32_FLOAT", {DXGI_FORMAT_R32_FLOAT, 4}, true, true, true},
    {"DXGI_FORMAT_R32G32_FLOAT", {DXGI_FORMAT_R32G32_FLOAT, 8}, true, true, true},
    {"DXGI_FORMAT_R32G32B32_FLOAT", {DXGI_FORMAT_R32G32B32_FLOAT, 12}, false, false, true},
    {"DXGI_FORMAT_R32G32B32A32_FLOAT", {DXGI_FORMAT_R32G32B32A32_FLOAT, 16}, true, true, true},
    {"DXGI_FORMAT_R32_TYPELESS",
     {DXGI_FORMAT_R32_TYPELESS, 4, DXGI_FORMAT_D32_FLOAT},
     true,
     false,
     false},
    {"DXGI_FORMAT_R24G8_TYPELESS",
     {DXGI_FORMAT_R24G8_TYPELESS, 4, DXGI_FORMAT_D24_UNORM_S8_UINT, 24},
     true,
     false,
     false},
    {"DXGI_FORMAT_R16_TYPELESS",
     {DXGI_FORMAT_R16_TYPELESS, 2, DXGI_FORMAT_D16_UNORM, 16},
     true,
     false,
     false},
    {"DXGI_FORMAT_R24_UNORM_X8_TYPELESS",
     {DXGI_FORMAT_R24_UNORM_X8_TYPELESS, 4},
     false,
     true,
     false},
    {"DXGI_FORMAT_R16_UNORM", {DXGI_FORMAT_R16_UNORM, 2}, false, true, false},
};

bool accepts(const FormatName& entry, FormatUse use) {
  switch (use) {
    case FormatUse::texture:
      return entry.texture;
    case FormatUse::view:
      return entry.view;
    case FormatUse::vertex:
      return entry.vertex;
  }
  return false;
}

const char* use_name(FormatUse use) {
  switch (use) {
    case FormatUse::texture:
      return "texture";
    case FormatUse::view:
      return "view";
    case FormatUse::vertex:
      return "vertex";
  }
  return "";
}

const char* stage_name(Stage stage) {
  return stage == Stage::vertex ? "vs" : "ps";
}

}  // namespace

std::string parse_format(const std::string& name, FormatUse use, DxgiFormat& format) {
  std::string allowed;
  for (const FormatName& entry : kFormats) {
    if (!accepts(entry, use)) continue;
    if (name == entry.name) {
      format = entry.format;
      return {};
    }
    allowed += (allowed.empty() ? "" : ", ") + std::string(entry.name);
  }
  return std::string(use_name(use)) + " format '" + name + "' (allowed: " + allowed + ")";
}

std::string check_texture(const TextureDesc& desc, DxgiFormat& format) {
  if (desc.width < 1 || desc.height < 1) {
    return "texture size " + std::to_string(desc.width) + "x" + std::to_string(desc.height);
  }
  int chain = 1;  // levels down to 1x1
  while ((desc.width | desc.height) >> chain) ++chain;
  if (desc.levels < 1 || desc.levels > chain) {
    return std::to_string(desc.levels) + " levels (allowed: 1 to " + std::to_string(chain) + ")";
  }
  if (std::string error = parse_format(desc.format, FormatUse::texture, format); !error.empty()) {
    return error;
  }
  const bool typeless = format.depth_view != DXGI_FORMAT_UNKNOWN;
  if ((desc.usage == Usage::depth) != typeless) {
    return "a depth texture is DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_R24G8_TYPELESS or "
           "DXGI_FORMAT_R16_TYPELESS, and only a depth texture is; not " +
           desc.format;
  }
  // The depth-stencil view writes level 0 only.
  if (desc.usage == Usage::depth && desc.levels != 1) return "a depth texture has one level";
  // Arrays are uploaded and sampled (map_layout array), never drawn into.
  if (desc.layers < 0 || (desc.layers > 0 && desc.usage == Usage::target)) {
    return std::to_string(desc.layers) + " layers (allowed: 0, a 2D texture; or more for an " +
           "input or depth array, which is uploaded, not drawn into)";
  }
  return {};
}

std::string check_copy(const TextureDesc& from, int src_level, const TextureDesc& to,
                       int dst_level) {
  const UINT width = level_size(from.width, src_level);
  const UINT height = level_size(from.height, src_level);
  const UINT to_width = level_size(to.width, dst_level);
  const UINT to_height = level_size(to.height, dst_level);
  const std::string what = std::to_string(width) + "x" + std::to_string(height) + " " +
                           from.format + " into " + std::to_string(to_width) + "x" +
                           std::to_string(to_height) + " " + to.format;
  if (from.format != to.format || width > to_width || height > to_height) {
    return what + ": the source must have the same format and be no larger";
  }
  // CopySubresourceRegion copies a depth-stencil resource's whole subresource only.
  const bool depth = from.usage == Usage::depth || to.usage == Usage::depth;
  if (depth && (width != to_width || height != to_height)) {
    return what + ": a depth texture is copied whole, into the same size";
  }
  return {};
}

std::string parse_register(const std::string& reg, char letter, UINT count, UINT& slot) {
  const std::string expected =
      std::string("register '") + letter + "<0.." + std::to_string(count - 1) + ">'";
  // Three digits hold every slot count of Direct3D 10 and 11 (at most 128).
  if (reg.size() < 2 || reg.size() > 4 || reg[0] != letter) {
    return expected + ", not '" + reg + "'";
  }
  slot = 0;
  for (std::size_t i = 1; i < reg.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(reg[i]))) return expected + ", not '" + reg + "'";
    slot = slot * 10 + static_cast<UINT>(reg[i] - '0');
  }
  if (slot >= count) return expected + ", not '" + reg + "'";
  return {};
}

std::string split_semantic(const std::string& semantic, std::string& name, UINT& index) {
  std::size_t digits = semantic.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(semantic[digits - 1]))) --digits;
  if (digits == 0 || semantic.size() - digits > 4) return "semantic '" + semantic + "'";
  name = semantic.substr(0, digits);
  index = 0;
  for (std::size_t i = digits; i < semantic.size(); ++i) {
    index = index * 10 + static_cast<UINT>(semantic[i] - '0');
  }
  return {};
}

std::string parse_sampler(const SamplerDesc& desc, SamplerSettings& settings) {
  if (desc.filter != "nearest" && desc.filter != "linear") {
    return "sampler filter '" + desc.filter + "' (allowed: nearest, linear)";
  }
  if (desc.mip_filter != "none" && desc.mip_filter != "nearest") {
    return "sampler mip_filter '" + desc.mip_filter + "' (allowed: none, nearest)";
  }
  if (desc.address != "clamp_to_edge") {
    return "sampler address '" + desc.address + "' (allowed: clamp_to_edge)";
  }
  settings.linear = desc.filter == "linear";
  settings.comparison = desc.comparison;
  settings.greater_equal = desc.comparison && desc.greater_equal;
  settings.mips = desc.mip_filter == "nearest";
  return {};
}

std::string pack_blocks(const std::vector<BlockMember>& members, UINT slots,
                        std::vector<ConstantBlock>& blocks) {
  blocks.clear();
  for (const BlockMember& member : members) {
    const std::string what = std::string("member ") + stage_name(member.stage) + " " + member.reg;
    UINT slot = 0;
    if (std::string error = parse_register(member.reg, 'b', slots, slot); !error.empty()) {
      return error + " (" + what + ")";
    }
    // A constant buffer is whole float4s, at most 4096 of them.
    if (member.block_size == 0 || member.block_size % 16 != 0 || member.block_size > 65536) {
      return what + ": block size " + std::to_string(member.block_size) +
             " (allowed: a multiple of 16, 16 to 65536)";
    }
    if (member.offset % 16 != 0 || member.offset + 16 > member.block_size) {
      return what + ": offset " + std::to_string(member.offset) +
             " (allowed: a multiple of 16 up to " + std::to_string(member.block_size - 16) + ")";
    }
    ConstantBlock* block = nullptr;
    for (ConstantBlock& b : blocks) {
      if (b.stage == member.stage && b.slot == slot) block = &b;
    }
    if (!block) {
      block = &blocks.emplace_back();
      block->stage = member.stage;
      block->slot = slot;
      block->bytes.assign(member.block_size, 0);
    }
    if (block->bytes.size() != member.block_size) {
      return what + ": block size " + std::to_string(member.block_size) + ", another member said " +
             std::to_string(block->bytes.size());
    }
    std::memcpy(block->bytes.data() + member.offset, member.value.data(), 16);
  }
  return {};
}

std::vector<float> read_rows(const void* data, UINT pitch, UINT row_bytes, UINT rows) {
  std::vector<float> texels(static_cast<std::size_t>(row_bytes / sizeof(float)) * rows);
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (UINT row = 0; row < rows; ++row) {
    std::memcpy(texels.data() + row * (row_bytes / sizeof(float)), bytes + row * pitch, row_bytes);
  }
  return texels;
}

std::vector<float> read_unorm_rows(const void* data, UINT pitch, UINT width, UINT rows,
                                   const DxgiFormat& format, unsigned shift) {
  std::vector<float> texels(std::size_t{width} * rows);
  const auto* bytes = static_cast<const unsigned char*>(data);
  const std::uint32_t mask = (std::uint32_t{1} << format.unorm_bits) - 1;
  for (UINT row = 0; row < rows; ++row) {
    for (UINT i = 0; i < width; ++i) {
      std::uint32_t texel = 0;  // little-endian, as every Direct3D device
      std::memcpy(&texel, bytes + row * pitch + i * format.bytes, format.bytes);
      // The code over 2^bits - 1, in double: exact to float's rounding.
      texels[std::size_t{row} * width + i] = float(double((texel >> shift) & mask) / double(mask));
    }
  }
  return texels;
}

void write_rows(std::span<const float> texels, UINT row_bytes, void* data, UINT pitch) {
  auto* bytes = static_cast<unsigned char*>(data);
  const std::size_t rows = texels.size() * sizeof(float) / row_bytes;
  for (std::size_t row = 0; row < rows; ++row) {
    std::memcpy(bytes + row * pitch, texels.data() + row * (row_bytes / sizeof(float)), row_bytes);
  }
}

std::string adapter_name(IUnknown* device, std::string& error) {
  Microsoft::WRL::ComPtr<IDXGIDevice> dxgi;
  HRESULT hr = device->QueryInterface(IID_PPV_ARGS(&dxgi));
  if (FAILED(hr)) {
    error = failed("QueryInterface(IDXGIDevice)", hr, "the device");
    return {};
  }
  Microsoft::WRL::ComPtr<IDXGIAdapter> adapter;
  if (hr = dxgi->GetAdapter(&adapter); FAILED(hr)) {
    error = failed("IDXGIDevice::GetAdapter", hr, "the device");
    return {};
  }
  DXGI_ADAPTER_DESC desc{};
  if (hr = adapter->GetDesc(&desc); FAILED(hr)) {
    error = failed("IDXGIAdapter::GetDesc", hr, "the adapter");
    return {};
  }
  char name[4 * sizeof desc.Description / sizeof(WCHAR)] = {};  // UTF-8 takes up to 4 bytes
  WideCharToMultiByte(CP_UTF8, 0, desc.Description, -1, name, sizeof name, nullptr, nullptr);
  return name;
}

std::string failed(const char* call, HRESULT hr, const std::string& what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%08lX", static_cast<unsigned long>(hr));
  return std::string(call) + " failed with HRESULT " + code + " (" + what + ")";
}

}  // namespace penumbra::d3dhost
