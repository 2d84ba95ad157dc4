#include "penumbra/shaders/library.hpp"

#include <algorithm>
#include <cstring>
#include <tuple>

namespace penumbra::shaders {
namespace {

auto order_key(std::string_view variant, Target target, PassKind pass) {
  return std::make_tuple(variant, static_cast<int>(target), static_cast<int>(pass));
}

auto order_key(const Program& p) {
  return order_key(p.variant, p.target, p.pass);
}

}  // namespace

Library::Library(std::span<const std::string_view> blob,
                 std::span<const EmbeddedProgram> programs) {
  for (std::string_view piece : blob) blob_.append(piece);
  auto text = [&](BlobRange r) { return std::string_view(blob_).substr(r.offset, r.size); };
  auto bytes = [&](BlobRange r) {
    return std::span<const std::uint8_t>(
        reinterpret_cast<const std::uint8_t*>(blob_.data()) + r.offset, r.size);
  };
  // SPIR-V is copied into word arrays: the blob's chars carry no alignment.
  auto words = [&](BlobRange r) -> std::span<const std::uint32_t> {
    std::vector<std::uint32_t>& out = words_.emplace_back(r.size / 4);
    std::memcpy(out.data(), blob_.data() + r.offset, out.size() * 4);
    return out;
  };
  std::size_t spirv_stages = 0;
  for (const EmbeddedProgram& e : programs) spirv_stages += e.target == Target::spirv ? 2 : 0;
  words_.reserve(spirv_stages);  // spans into words_ stay valid
  for (const EmbeddedProgram& e : programs) {
    Program p;
    p.variant = e.variant;
    p.target = e.target;
    p.pass = e.pass;
    p.reflection = text(e.reflection);
    for (auto [stage, code, bytecode, profile] :
         {std::tuple{&p.vertex, e.vertex, e.vertex_bytecode, e.vertex_profile},
          std::tuple{&p.fragment, e.fragment, e.fragment_bytecode, e.fragment_profile}}) {
      if (e.target == Target::spirv) {
        stage->spirv = words(code);
      } else {
        stage->text = text(code);
      }
      stage->bytecode = bytes(bytecode);
      stage->profile = profile;
    }
    programs_.push_back(p);
  }
  std::ranges::sort(programs_, {}, [](const Program& p) { return order_key(p); });
}

const Program* Library::find(std::string_view variant, Target target, PassKind pass) const {
  const auto key = order_key(variant, target, pass);
  const auto it =
      std::ranges::lower_bound(programs_, key, {}, [](const Program& p) { return order_key(p); });
  return it != programs_.end() && order_key(*it) == key ? &*it : nullptr;
}

const Program* Library::find(Technique technique, const VariantKeys& keys, Target target,
                             PassKind pass) const {
  return find(variant_name(technique, keys), target, pass);
}

}  // namespace penumbra::shaders
