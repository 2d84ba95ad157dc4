// The shader library's source files, embedded at build time.
#pragma once

#include <optional>
#include <string_view>

namespace penumbra::shaderlib {

// The text of a file by its path relative to shaderlib/ ("passes/query.frag").
std::optional<std::string_view> file(std::string_view path);

}  // namespace penumbra::shaderlib
