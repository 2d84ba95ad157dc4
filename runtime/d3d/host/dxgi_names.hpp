// What the Direct3D 10 and 11 devices share: the job's DXGI format,
// register, semantic and sampler-state names read into API terms, constant
// buffers packed from their members, mapped rows read back, and the
// one-line messages of failed calls.
#pragma once

#include <dxgiformat.h>
#include <windows.h>

#include <compare>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "device.hpp"

namespace penumbra::d3dhost {

// 32-bit float channels, or a depth map's typeless texture or its unorm view.
struct DxgiFormat {
  DXGI_FORMAT format = DXGI_FORMAT_UNKNOWN;
  unsigned bytes = 0;  // per texel or vertex element
  // A typeless depth texture's depth-stencil view format; UNKNOWN for the rest.
  DXGI_FORMAT depth_view = DXGI_FORMAT_UNKNOWN;
  // A unorm depth texture's depth bits (24, 16), read back as code / (2^bits - 1);
  // 0 for float texels.
  unsigned unorm_bits = 0;
};

// What a format name is read for; each accepts its own names.
enum class FormatUse { texture, view, vertex };

// `name` as a format for `use`; an error lists the names allowed.
std::string parse_format(const std::string& name, FormatUse use, DxgiFormat& format);

// Checks `desc` (sizes, and a typeless depth format exactly for Usage::depth,
// with one level) and reads its format.
std::string check_texture(const TextureDesc& desc, DxgiFormat& format);

// Why level `src_level` of `from` may not go to texel (0, 0) of level
// `dst_level` of `to` (device.hpp's copy()); empty if it may.
std::string check_copy(const TextureDesc& from, int src_level, const TextureDesc& to,
                       int dst_level);

// Level `level`'s width or height for a level-0 `size`.
inline UINT level_size(int size, int level) {
  return size >> level > 1 ? size >> level : 1;
}

// "t1" with `letter` 't' is slot 1; slots 0 to count - 1 are allowed.
std::string parse_register(const std::string& reg, char letter, UINT count, UINT& slot);

// "TEXCOORD0" is `name` "TEXCOORD", `index` 0; "POSITION" is index 0.
std::string split_semantic(const std::string& semantic, std::string& name, UINT& index);

// A sampler state in API-neutral terms, ordered so it can key a cache.
struct SamplerSettings {
  bool linear = false;         // MIN_MAG_LINEAR_MIP_POINT, else MIN_MAG_MIP_POINT
  bool comparison = false;     // the COMPARISON_ filter with LESS_EQUAL, else NEVER
  bool greater_equal = false;  // with comparison: GREATER_EQUAL
  bool mips = false;           // MaxLOD FLOAT32_MAX (point mips), else 0 (level 0 only)
  auto operator<=>(const SamplerSettings&) const = default;
};

std::string parse_sampler(const SamplerDesc& desc, SamplerSettings& settings);

// One constant buffer's contents: the members of one (stage, register).
struct ConstantBlock {
  Stage stage = Stage::pixel;
  UINT slot = 0;
  std::vector<unsigned char> bytes;  // block_size bytes, zero where no member is
};

// Groups `members` by (stage, register) into `blocks`; `slots` is the
// API's constant-buffer slot count.
std::string pack_blocks(const std::vector<BlockMember>& members, UINT slots,
                        std::vector<ConstantBlock>& blocks);

// `rows` mapped rows `pitch` bytes apart, `row_bytes` of texels each, as floats.
std::vector<float> read_rows(const void* data, UINT pitch, UINT row_bytes, UINT rows);

// The depth of `rows` rows of `width` texels of a unorm depth format (its
// depth in `format.unorm_bits` bits of each texel, `shift` bits from bit 0),
// as floats in [0, 1].
std::vector<float> read_unorm_rows(const void* data, UINT pitch, UINT width, UINT rows,
                                   const DxgiFormat& format, unsigned shift);
// The other way: `texels`' rows of `row_bytes` into mapped rows `pitch` bytes apart.
void write_rows(std::span<const float> texels, UINT row_bytes, void* data, UINT pitch);

// The adapter's description (IDXGIAdapter::GetDesc) of a Direct3D 10 or 11
// device, as UTF-8; empty, with `error` set, if it cannot be had.
std::string adapter_name(IUnknown* device, std::string& error);

// "CreateTexture2D failed with HRESULT 0x80070057 (texture 3)".
std::string failed(const char* call, HRESULT hr, const std::string& what);

// The entry of `map` under `id`, or null.
template <typename T>
T* find_id(std::map<int, T>& map, int id) {
  const auto it = map.find(id);
  return it == map.end() ? nullptr : &it->second;
}

}  // namespace penumbra::d3dhost
