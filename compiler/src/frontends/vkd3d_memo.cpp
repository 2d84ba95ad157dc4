#include "penumbra/compiler/bytecode_frontend.hpp"

namespace penumbra {
namespace {

template <typename Value>
std::optional<Value> find_in(const std::unordered_map<std::string, Value>& values,
                             const std::string& key) {
  const auto found = values.find(key);
  if (found == values.end()) return std::nullopt;
  return found->second;
}

}  // namespace

std::optional<std::string> Vkd3dMemo::find_bytecode(const std::string& key) const {
  const std::lock_guard lock(mutex_);
  return find_in(bytecode_, key);
}

std::optional<FrontEndResult> Vkd3dMemo::find_spirv(const std::string& key) const {
  const std::lock_guard lock(mutex_);
  return find_in(spirv_, key);
}

void Vkd3dMemo::add_bytecode(std::string key, std::string bytecode) {
  const std::lock_guard lock(mutex_);
  bytecode_.try_emplace(std::move(key), std::move(bytecode));
}

void Vkd3dMemo::add_spirv(std::string key, FrontEndResult spirv) {
  const std::lock_guard lock(mutex_);
  spirv_.try_emplace(std::move(key), std::move(spirv));
}

}  // namespace penumbra
