#include "built_library.hpp"

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "default_library.hpp"
#include "penumbra/model/shader_contract.hpp"

namespace penumbra::testing {

Result<const Library*> default_library_of(const std::string& name,
                                          const std::vector<Target>& targets) {
  static std::map<std::pair<std::string, std::vector<Target>>, std::unique_ptr<TemporaryLibrary>>
      built;
  const auto key = std::make_pair(name, targets);
  if (const auto found = built.find(key); found != built.end()) return &found->second->library();
  PENUMBRA_TRY_ASSIGN(auto library, build_default_variant(name, key.second));
  return &built.emplace(key, std::move(library)).first->second->library();
}

Status prove_default_variant(const std::string& name, Prover prover,
                             const std::vector<Target>& targets) {
  PENUMBRA_TRY_ASSIGN(const Library* library, default_library_of(name, targets));
  const LibraryVariant* variant = library->find(name);
  if (variant == nullptr) {
    return make_error(Error::Kind::internal, name, "the built library lacks the variant");
  }
  std::string failures;
  for (const Target target : targets) {
    if (!can_emit(variant->variant, target)) continue;
    int proved = 0;
    for (const auto& [pass, files] : variant->passes) {
      if (!files.contains(target)) continue;
      ++proved;
      if (auto status = prover(*library, *variant, pass, target); !status) {
        failures += "\n" + status.error().to_string();
      }
    }
    if (proved == 0)
      failures += "\n" + name + ": no pass is built for " + std::string(to_string(target));
  }
  if (failures.empty()) return {};
  return make_error(Error::Kind::compile, name, "reflection not proved:" + failures);
}

}  // namespace penumbra::testing
