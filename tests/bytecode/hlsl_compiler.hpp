// The vkd3d-compiler that CMake recorded at configure time, for the
// bytecode tests.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include "penumbra/support/result.hpp"

namespace penumbra::testing {

// The recorded compiler, or an error saying how to get one: the tests that
// need it fail without it (CI must run them), they do not skip.
inline Result<std::filesystem::path> recorded_hlsl_compiler() {
  const std::filesystem::path path = PENUMBRA_HLSL_COMPILER;
  if (::access(path.c_str(), X_OK) == 0) return path;
  return make_error(Error::Kind::io, "PENUMBRA_HLSL_COMPILER",
                    "no vkd3d-compiler recorded at configure time (\"" + path.string() +
                        "\"): run scripts/test.sh, or scripts/lib/sid-tools.sh vkd3d and "
                        "then cmake -DPENUMBRA_HLSL_COMPILER=PATH");
}

}  // namespace penumbra::testing
