// Runs every essl300 program of a built library through Chromium's WebGL 2
// in one headless browser run (webgl_proof.html), and returns what WebGL
// reports of each: compile and link logs, active uniforms, uniform blocks
// and attributes, the reflection's names resolved as an engine resolves
// them, and which float formats render with and without
// EXT_color_buffer_float. The JSON's shape is webgl_proof.html's.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "penumbra/library/library.hpp"

namespace penumbra::testing {

// webgl_proof.html's result object. Errors name the page (kept, with the
// browser's log, when the run fails), the exit status and the log.
Result<nlohmann::json> run_webgl(const Library& library);

// The key of a program in the result: "<vert file>|<frag file>".
std::string program_key(const PassFiles& files);

}  // namespace penumbra::testing
