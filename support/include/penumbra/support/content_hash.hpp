// A 128-bit content hash (XXH3) of a sequence of fields, for cache keys.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace penumbra {

class ContentHash {
 public:
  ContentHash();
  ~ContentHash();
  ContentHash(const ContentHash&) = delete;
  ContentHash& operator=(const ContentHash&) = delete;

  // Adds one field. Each field is length-prefixed, so ("ab", "c") and
  // ("a", "bc") hash differently.
  ContentHash& add(std::string_view field);
  ContentHash& add(std::span<const std::uint32_t> words);
  ContentHash& add(std::uint64_t value);

  // 32 lowercase hex digits of the fields added so far.
  std::string hex() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The hex hash of one string.
std::string content_hash(std::string_view bytes);

// The running executable's GNU build ID (its .note.gnu.build-id) as hex:
// it changes whenever the linked code does. Empty when the linker wrote none.
std::string executable_build_id();

}  // namespace penumbra
