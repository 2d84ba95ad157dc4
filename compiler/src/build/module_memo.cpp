#include "build/module_memo.hpp"

#include <algorithm>

#include "penumbra/compiler/build.hpp"
#include "penumbra/support/content_hash.hpp"

namespace penumbra {

std::string module_key(const ShaderJob& job) {
  ContentHash key;
  key.add(to_string(job.stage)).add(job.form == ShaderForm::function ? "function" : "pass");
  key.add(job.source_path).add(job.variant ? variant_identity(*job.variant) : std::string());
  key.add(job.preprocessed);
  return key.hex();
}

std::optional<Module> ModuleMemo::find(const std::string& key) const {
  const std::scoped_lock lock(mutex_);
  const auto found = std::ranges::find(modules_, key, &decltype(modules_)::value_type::first);
  if (found == modules_.end()) return std::nullopt;
  return found->second;
}

void ModuleMemo::add(const std::string& key, Module module) {
  const std::scoped_lock lock(mutex_);
  modules_.emplace_back(key, std::move(module));
  if (modules_.size() > capacity_) modules_.pop_front();
}

}  // namespace penumbra
