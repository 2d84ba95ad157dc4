#include "penumbra/support/content_hash.hpp"

// Header-only use of libxxhash: the package needs no xxhash at link time.
#define XXH_INLINE_ALL
#include <xxhash.h>

#include <cstdio>

namespace penumbra {

struct ContentHash::State {
  XXH3_state_t xxh{};
};

ContentHash::ContentHash() : state_(std::make_unique<State>()) {
  XXH3_128bits_reset(&state_->xxh);
}

ContentHash::~ContentHash() = default;

ContentHash& ContentHash::add(std::string_view field) {
  const std::uint64_t size = field.size();
  XXH3_128bits_update(&state_->xxh, &size, sizeof size);
  XXH3_128bits_update(&state_->xxh, field.data(), field.size());
  return *this;
}

ContentHash& ContentHash::add(std::span<const std::uint32_t> words) {
  return add(std::string_view(reinterpret_cast<const char*>(words.data()), words.size_bytes()));
}

ContentHash& ContentHash::add(std::uint64_t value) {
  XXH3_128bits_update(&state_->xxh, &value, sizeof value);
  return *this;
}

std::string ContentHash::hex() const {
  const XXH128_hash_t hash = XXH3_128bits_digest(&state_->xxh);
  char text[33];
  std::snprintf(text, sizeof text, "%016llx%016llx", static_cast<unsigned long long>(hash.high64),
                static_cast<unsigned long long>(hash.low64));
  return text;
}

std::string content_hash(std::string_view bytes) {
  return ContentHash().add(bytes).hex();
}

}  // namespace penumbra
