// The output directory of a build or merge.
#pragma once

#include <filesystem>

#include "penumbra/support/result.hpp"

namespace penumbra {

// OUT is replaced wholesale, so it must be absent, empty, or a library that
// an earlier build wrote (it has index.json): never a user's file or folder.
Status check_replaceable(const std::filesystem::path& out);

}  // namespace penumbra
