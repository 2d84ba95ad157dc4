// OUT/index.json (docs/shader-interface.md) from the jobs of a finished build.
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <vector>

#include "penumbra/compiler/stage.hpp"

namespace penumbra {

nlohmann::json variant_keys_json(const VariantKeys& keys);

// `jobs` holds every finished job: shared ones (variant == null) and each
// variant's own.
nlohmann::json index_json(std::span<const Variant> variants, const std::vector<ShaderJob>& jobs);

}  // namespace penumbra
