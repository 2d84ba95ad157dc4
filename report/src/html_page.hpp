// The report's static HTML page: report.json in a self-contained page
// (report_page.html: no network, no external assets) whose script draws the
// table, sorts it by any column and filters it by technique, target and path.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace penumbra::report {

// `cost_chart_svg` is placed inline, as it is (cost_chart_svg()).
std::string html_page(const nlohmann::json& report, std::string_view cost_chart_svg);

}  // namespace penumbra::report
