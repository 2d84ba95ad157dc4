// Headless Chromium running one test page and handing back what the page
// wrote into its <pre id="result">: WebGL 2 on ANGLE's SwiftShader, so that
// no GPU is needed. tests/webgl and tests/threejs drive their pages with it.
#pragma once

#include <filesystem>
#include <string>

#include "penumbra/support/result.hpp"

namespace penumbra::testing {

// The text of `page`'s <pre id="result"> after the page has loaded, its
// entities unescaped. `chromium` is the browser's executable. Errors name
// the page with the browser's exit status and log (kept beside the page),
// or say that the page wrote no result.
Result<std::string> run_chromium_page(const std::filesystem::path& page,
                                      const std::string& chromium);

// `text` inside <script>: "</" would end the element.
std::string script_safe(const std::string& text);

}  // namespace penumbra::testing
