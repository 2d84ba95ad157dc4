// The report's static HTML page: report.json in a self-contained page
// (report_page.html: no network, no external assets) whose script draws the
// table, sorts it by any column and filters it by technique, target and path.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace penumbra::report {

std::string html_page(const nlohmann::json& report);

}  // namespace penumbra::report
