// OUT/index.json (docs/shader-interface.md) from the jobs of a finished build.
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "penumbra/compiler/stage.hpp"

namespace penumbra {

nlohmann::json variant_keys_json(const VariantKeys& keys);

// `jobs` holds every finished job: shared ones (variant == null) and each
// variant's own.
nlohmann::json index_json(std::span<const Variant> variants, const std::vector<ShaderJob>& jobs);

// index.json's text: each top-level member on a line of its own, and each
// record of a top-level array (a variant, a reflection record, a disk) on
// one line (one variant a line: grep finds it). Indenting every nested
// member, as dump(2) does, made over half of the file whitespace and each
// variant hundreds of lines.
std::string index_text(const nlohmann::json& index);

}  // namespace penumbra
