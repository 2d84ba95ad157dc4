// Compares one pass's essl300 reflection with what WebGL 2 reports of its
// program (one entry of webgl_proof.html's `programs`), in both directions.
// WebGL reports per program, not per stage, so both sides are written per
// program, as Facts: one line per entry ("block ShadowParams member
// ShadowParams.light" -> "vec4 at 16"); a block says which stages use it
// (UNIFORM_BLOCK_REFERENCED_BY_*_SHADER). Fragment outputs cannot be listed
// in WebGL: they are checked one way, by getFragDataLocation.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "penumbra/model/target_reflection.hpp"

namespace penumbra::testing {

// Entry -> what the side says of it.
using Facts = std::map<std::string, std::string>;

Facts reflected_facts(const PassReflection& pass);
Facts webgl_facts(const nlohmann::json& program);

// One line per difference: the program did not compile or link, an entry
// differs, is missing from WebGL or from the reflection, a reflection name
// that WebGL's lookup (getUniformBlockIndex, getUniformIndices,
// getUniformLocation, getAttribLocation) does not find, or a render-target
// format or extension the browser's result contradicts. `browser` is the
// whole result (extensions, framebuffers).
std::vector<std::string> check_pass(const PassReflection& pass, const nlohmann::json& program,
                                    const nlohmann::json& browser);

}  // namespace penumbra::testing
