// What report.cpp and the page write that depends on the run's timings.
#include <nlohmann/json.hpp>

#include "penumbra/report/report.hpp"

namespace penumbra {
namespace {

// report.json's text less gpu_cost and each row's run_ms.
std::string untimed_json(const std::string& text) {
  nlohmann::json report = nlohmann::json::parse(text);
  report.erase("gpu_cost");
  for (nlohmann::json& row : report["rows"]) row.erase("run_ms");
  return report.dump();
}

// `text` less the part from `begin` to the end of the first `end` after it.
void cut(std::string& text, std::string_view begin, std::string_view end) {
  const std::size_t from = text.find(begin);
  const std::size_t to = text.find(end, from);
  if (from != std::string::npos && to != std::string::npos) {
    text.erase(from, to + end.size() - from);
  }
}

}  // namespace

std::map<std::string, std::string> untimed_report_files(std::map<std::string, std::string> files) {
  files.erase("cost_chart.png");
  if (auto json = files.find("report.json"); json != files.end()) {
    json->second = untimed_json(json->second);
  }
  if (auto page = files.find("index.html"); page != files.end()) {
    std::string& html = page->second;
    cut(html, "<svg id=\"cost-chart\"", "</svg>");
    // The page embeds report.json (report_page.html's report-data).
    const std::string_view data = "id=\"report-data\">";
    const std::size_t from = html.find(data);
    const std::size_t to = html.find("</script>", from);
    if (from != std::string::npos && to != std::string::npos) {
      const std::size_t start = from + data.size();
      html.replace(start, to - start, untimed_json(html.substr(start, to - start)));
    }
  }
  return files;
}

}  // namespace penumbra
