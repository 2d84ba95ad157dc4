// The report as a user gets it: `penumbra build` of the default library,
// `penumbra report`, and the page opened in headless Chromium. The page must
// render with no console message and no missing picture, show a row for
// every (variant, target, path), link only to files that exist, chart every
// spirv variant's error against its GPU time and texel reads with the Pareto
// front marked, and its screenshot is kept as a test artifact. The CLI's refusals are checked on
// the same library.
#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "cli_harness.hpp"
#include "default_library.hpp"
#include "penumbra/model/map_encoding.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;

// Headless as root on a machine with no GPU, nothing reaching the network,
// console messages logged to stderr, and time for the page's pictures and
// script before the DOM is read.
constexpr const char* kChromiumFlags =
    " --headless --no-sandbox --disable-gpu --disable-background-networking"
    " --disable-component-update --disable-sync --no-first-run --hide-scrollbars"
    " --enable-logging=stderr --v=0 --virtual-time-budget=10000";

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The body rows of the page's table: each <tr>'s attributes and the text
// of its cells (a cell's markup, for cells holding pictures or links).
std::vector<std::pair<std::string, std::vector<std::string>>> table_rows(const std::string& page) {
  std::vector<std::pair<std::string, std::vector<std::string>>> rows;
  const std::size_t body = page.find("<tbody");
  for (std::size_t at = page.find("<tr", body); at != std::string::npos;
       at = page.find("<tr", at + 3)) {
    const std::size_t open_end = page.find('>', at);
    const std::size_t close = page.find("</tr>", open_end);
    if (open_end == std::string::npos || close == std::string::npos) break;
    std::vector<std::string> cells;
    for (std::size_t c = page.find("<td", open_end); c != std::string::npos && c < close;
         c = page.find("<td", c + 3)) {
      const std::size_t text = page.find('>', c) + 1;
      cells.push_back(page.substr(text, page.find("</td>", text) - text));
    }
    rows.emplace_back(page.substr(at + 3, open_end - at - 3), std::move(cells));
  }
  return rows;
}

class ReportInBrowser : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new ScratchDir("report-browser");
    const CliRun build =
        run_penumbra("build " + quoted(PENUMBRA_SOURCE_DIR "/permutations/default.json") + " -o " +
                     quoted(lib().string()) + " --no-cache -j 2");
    ASSERT_EQ(build.exit_code, 0) << build.err;
    // The Direct3D runtimes' rows: tests/d3d/cli_report_test.cpp (here they
    // would double the report's time).
    const CliRun report = run_penumbra("report " + quoted(lib().string()) + " --no-wine");
    ASSERT_EQ(report.exit_code, 0) << report.err;
    ASSERT_NE(report.out.find((report_dir() / "index.html").string()), std::string::npos)
        << report.out;
    json_ = nlohmann::json::parse(read_text(report_dir() / "report.json"));
    // One run for the DOM and the console, one for the screenshot.
    ASSERT_EQ(chromium("--dump-dom " + url(""), "dom.html", "chromium.log"), 0)
        << read_text(dir_->path() / "chromium.log");
    fs::create_directories(PENUMBRA_ARTIFACT_DIR);
    ASSERT_EQ(chromium("--window-size=1600,2000 --screenshot=" + quoted(screenshot().string()) +
                           " " + url(""),
                       "screenshot.out", "screenshot.log"),
              0);
  }

  // Runs Chromium on `args`, its stdout and stderr into the scratch folder.
  static int chromium(const std::string& args, const std::string& out, const std::string& log) {
    return std::system(("timeout 300 " + quoted(CHROMIUM_EXECUTABLE) + kChromiumFlags +
                        " --user-data-dir=" + quoted((dir_->path() / "profile").string()) + " " +
                        args + " > " + quoted((dir_->path() / out).string()) + " 2> " +
                        quoted((dir_->path() / log).string()))
                           .c_str());
  }
  static std::string url(const std::string& fragment) {
    return quoted("file://" + (report_dir() / "index.html").string() + fragment);
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }

  static fs::path lib() { return dir_->path() / "lib"; }
  static fs::path report_dir() { return lib() / "report"; }
  static fs::path screenshot() { return fs::path(PENUMBRA_ARTIFACT_DIR) / "report.png"; }
  static std::string dom() { return read_text(dir_->path() / "dom.html"); }

  static inline ScratchDir* dir_ = nullptr;
  static inline nlohmann::json json_;
};

// The default variants whose map is orthographic: their directional light
// is not the report stage's, so the report leaves them unmeasured.
std::set<std::string> orthographic_variants() {
  std::set<std::string> out;
  for (const Variant& variant : default_variants()) {
    if (is_orthographic(map_encoding(variant.keys))) out.insert(variant.name);
  }
  return out;
}

TEST_F(ReportInBrowser, RendersWithNoConsoleMessageAndNoMissingPicture) {
  const std::string log = read_text(dir_->path() / "chromium.log");
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_EQ(line.find(":CONSOLE"), std::string::npos) << line;
  }
  const std::string page = dom();
  ASSERT_NE(page.find("<tbody id=\"rows\">"), std::string::npos) << "the page did not render";
  // The page names any script error or picture that did not load in #errors.
  std::smatch errors;
  ASSERT_TRUE(
      std::regex_search(page, errors, std::regex(R"(<div id="errors"[^>]*>([^<]*)</div>)")));
  EXPECT_EQ(errors[1].str(), "");
}

TEST_F(ReportInBrowser, ShowsARowForEveryVariantTargetAndPath) {
  const std::string page = dom();
  const nlohmann::json& rows = json_.at("rows");
  // The script marks the rows it drew on <body>.
  EXPECT_NE(page.find("data-rows=\"" + std::to_string(rows.size()) + "\""), std::string::npos);
  const std::set<std::string> orthographic = orthographic_variants();
  std::set<std::pair<std::string, std::string>> pairs;
  for (const auto& row : rows) {
    // The Direct3D runtimes' rows are skipped here (--no-wine), and say so;
    // so are an orthographic map's, whose directional light is not the
    // stage's.
    const bool skipped = row.at("path").get<std::string>().starts_with("d3d") ||
                         orthographic.contains(row.at("variant").get<std::string>());
    EXPECT_EQ(row.at("status"), skipped ? "not executed" : "ok") << row.dump();
    pairs.emplace(row.at("variant"), row.at("target"));
  }
  for (const Variant& variant : default_variants()) {
    EXPECT_TRUE(std::regex_search(page, std::regex("<td[^>]*>" + variant.name + "</td>")))
        << variant.name;
    for (Target target : variant.targets) {
      EXPECT_TRUE(pairs.contains({variant.name, std::string(to_string(target))}))
          << variant.name << " " << to_string(target);
    }
  }
}

TEST_F(ReportInBrowser, EveryLinkResolvesInsideTheReportOrTheLibrary) {
  std::size_t links = 0;
  for (const auto& row : json_.at("rows")) {
    // A run not executed has no pictures, only its files.
    for (const char* key : {"image", "exact_error_image", "reference_error_image"}) {
      if (row.at("status") != "ok") break;
      EXPECT_TRUE(fs::is_regular_file(report_dir() / row.at(key).get<std::string>())) << row.dump();
      ++links;
    }
    for (const auto& file : row.at("files")) {
      EXPECT_TRUE(fs::is_regular_file(report_dir() / file.at("href").get<std::string>()))
          << file.dump();
      ++links;
    }
  }
  EXPECT_GT(links, 4 * json_.at("rows").size());
  EXPECT_TRUE(fs::is_regular_file(report_dir() / "truth.png"));
  EXPECT_TRUE(fs::is_regular_file(report_dir() / "contact_sheet.png"));
}

TEST_F(ReportInBrowser, FiguresRankTheTechniquesAsThePapersDo) {
  // Against the exact square light, on the SPIR-V runs: the hard shadow is
  // the worst in the penumbra; PCSS beats fixed-width PCF; back-projection
  // beats the whitepaper's PCSS.
  std::map<std::string, double> mae;
  for (const auto& row : json_.at("rows")) {
    if (row.at("target") != "spirv" || row.at("status") != "ok") continue;
    mae[row.at("variant")] = row.at("figures").at("exact_penumbra_mae");
  }
  for (const auto& [name, error] : mae) {
    if (!name.starts_with("hard")) {  // hard and hard on an engine's maps
      EXPECT_LT(error, mae.at("hard")) << name;
    }
  }
  // A map in an engine's encoding shows what the library's linear map does.
  for (const std::string suffix : {"_perspective", "_perspective_reversed"}) {
    for (const auto& [name, error] : mae) {
      if (!name.ends_with(suffix)) continue;
      const std::string linear = name.substr(0, name.size() - suffix.size());
      ASSERT_TRUE(mae.contains(linear)) << name;
      EXPECT_NEAR(error, mae.at(linear), 1e-4) << name;
    }
  }
  EXPECT_LT(mae.at("pcss_b16_p16_whitepaper16"), mae.at("pcf_poisson_p16_whitepaper16"));
  EXPECT_LT(mae.at("backprojection"), mae.at("pcss_b16_p16_whitepaper16"));
}

// The cost chart, inline SVG: per panel one point per timed variant, the
// Pareto front (the points no other variant beats on both cost and error,
// recomputed here from report.json) ringed, joined and labelled, and a
// legend of the techniques; report.json holds the GPU times it plots.
TEST_F(ReportInBrowser, ChartsErrorAgainstGpuTimeAndTexelReadsWithTheParetoFront) {
  const nlohmann::json& timed = json_.at("gpu_cost").at("variants");
  std::set<std::string> expected, names, techniques;
  for (const Variant& variant : default_variants()) {
    // An orthographic map's directional light is not the stage's: untimed.
    if (std::ranges::find(variant.targets, Target::spirv) != variant.targets.end() &&
        !is_orthographic(map_encoding(variant.keys))) {
      expected.insert(variant.name);
    }
  }
  for (const auto& v : timed) {
    names.insert(v.at("variant").get<std::string>());
    techniques.insert(v.at("technique").get<std::string>());
    EXPECT_GT(v.at("query_ms").get<double>(), 0.0) << v.dump();
    EXPECT_GT(v.at("depth_ms").get<double>(), 0.0) << v.dump();
    EXPECT_DOUBLE_EQ(v.at("gpu_ms").get<double>(), v.at("depth_ms").get<double>() +
                                                       v.at("mip_ms").get<double>() +
                                                       v.at("query_ms").get<double>())
        << v.dump();
  }
  EXPECT_EQ(names, expected);
  EXPECT_GE(json_.at("gpu_cost").at("runs").get<int>(), 5);

  const std::string page = dom();
  const std::size_t chart = page.find("<svg id=\"cost-chart\"");
  ASSERT_NE(chart, std::string::npos) << "no cost chart";
  for (const char* axis : {"gpu_ms", "texel_reads"}) {
    SCOPED_TRACE(axis);
    const std::size_t begin = page.find(std::string("data-axis=\"") + axis + "\"", chart);
    ASSERT_NE(begin, std::string::npos);
    const std::string panel = page.substr(begin, page.find("</g>", begin) - begin);
    const std::string key = std::string(axis) == "gpu_ms" ? "gpu_ms" : "texel_reads_per_pixel";
    // A point is on the front unless another beats it (or equals it, first).
    std::set<std::string> front;
    for (std::size_t i = 0; i < timed.size(); ++i) {
      const double cost = timed[i].at(key), error = timed[i].at("exact_penumbra_mae");
      bool beaten = false;
      for (std::size_t j = 0; j < timed.size() && !beaten; ++j) {
        const double c = timed[j].at(key), e = timed[j].at("exact_penumbra_mae");
        beaten = j != i && c <= cost && e <= error && (c < cost || e < error || j < i);
      }
      if (!beaten) front.insert(timed[i].at("variant").get<std::string>());
    }
    ASSERT_FALSE(front.empty());
    std::set<std::string> points, marked;
    const std::regex point(
        R"re(<circle class="point( pareto)?" data-variant="([^"]+)" data-technique="([^"]+)")re");
    for (std::sregex_iterator it(panel.begin(), panel.end(), point), end; it != end; ++it) {
      EXPECT_TRUE(points.insert((*it)[2]).second) << "twice: " << (*it)[2];
      if ((*it)[1].matched) marked.insert((*it)[2]);
    }
    EXPECT_EQ(points, names);
    EXPECT_EQ(marked, front);
    EXPECT_NE(panel.find("<polyline class=\"pareto-front\""), std::string::npos);
    for (const std::string& name : front) {
      EXPECT_TRUE(std::regex_search(
          panel, std::regex("<text class=\"point-label\"[^>]*>" + name + "</text>")))
          << name;
    }
  }
  for (const std::string& technique : techniques) {
    EXPECT_TRUE(std::regex_search(
        page, std::regex("<text class=\"technique-label\"[^>]*>" + technique + "</text>")))
        << technique;
  }
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  const fs::path png = report_dir() / json_.at("gpu_cost").at("chart_image").get<std::string>();
  ASSERT_NE(png_image_begin_read_from_file(&image, png.c_str()), 0) << png;
  EXPECT_GT(image.width, 1000u);
  png_image_free(&image);
}

// The view in the address's fragment: the rows shown are the filter's, in
// the order of the sorted column.
TEST_F(ReportInBrowser, SortsAndFiltersAsTheAddressSays) {
  ASSERT_EQ(chromium("--dump-dom " + url("#sort=exact_penumbra_mae&order=down&technique=pcss&"
                                         "target=spirv"),
                     "sorted.html", "sorted.log"),
            0);
  const std::string page = read_text(dir_->path() / "sorted.html");
  const std::set<std::string> orthographic_names = orthographic_variants();
  std::vector<double> shown;
  std::size_t hidden = 0, unmeasured = 0;
  for (const auto& [attributes, cells] : table_rows(page)) {
    if (attributes.find("hidden") != std::string::npos) {
      ++hidden;
      continue;
    }
    EXPECT_NE(attributes.find("data-technique=\"pcss\""), std::string::npos) << attributes;
    EXPECT_NE(attributes.find("data-target=\"spirv\""), std::string::npos) << attributes;
    ASSERT_GT(cells.size(), 6u);
    // An orthographic variant's row is not executed: it has no figures.
    if (orthographic_names.contains(cells[1])) {
      ++unmeasured;
      continue;
    }
    shown.push_back(std::stod(cells[6]));  // exact_penumbra_mae
  }
  std::size_t pcss = 0, orthographic = 0;
  for (const Variant& variant : default_variants()) {
    if (variant.technique != Technique::pcss) continue;
    ++pcss;
    orthographic += is_orthographic(map_encoding(variant.keys)) ? 1 : 0;
  }
  EXPECT_EQ(unmeasured, orthographic);
  EXPECT_EQ(shown.size() + unmeasured, pcss);
  EXPECT_EQ(shown.size() + unmeasured + hidden, json_.at("rows").size());
  EXPECT_TRUE(std::is_sorted(shown.rbegin(), shown.rend())) << "not descending";
}

TEST_F(ReportInBrowser, ScreenshotIsKept) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  ASSERT_NE(png_image_begin_read_from_file(&image, screenshot().c_str()), 0) << screenshot();
  EXPECT_EQ(image.width, 1600u);
  EXPECT_EQ(image.height, 2000u);
  png_image_free(&image);
}

TEST_F(ReportInBrowser, RefusesBadArgumentsAndForeignFolders) {
  const CliRun variant = run_penumbra("report " + quoted(lib().string()) + " --variant nope");
  EXPECT_EQ(variant.exit_code, 2);
  EXPECT_NE(variant.err.find("--variant nope"), std::string::npos) << variant.err;
  const CliRun target = run_penumbra("report " + quoted(lib().string()) + " --target dx12");
  EXPECT_EQ(target.exit_code, 2);
  EXPECT_NE(target.err.find("allowed:"), std::string::npos) << target.err;
  // A folder of the user's is never replaced, and nothing is written.
  const fs::path mine = dir_->path() / "mine";
  fs::create_directories(mine);
  std::ofstream(mine / "notes.txt") << "keep";
  const CliRun foreign = run_penumbra("report " + quoted(lib().string()) + " -o " +
                                      quoted(mine.string()) + " --variant hard");
  EXPECT_EQ(foreign.exit_code, 2);
  EXPECT_NE(foreign.err.find("not a penumbra report"), std::string::npos) << foreign.err;
  EXPECT_EQ(read_tree(mine), (std::map<std::string, std::string>{{"notes.txt", "keep"}}));
}

}  // namespace
}  // namespace penumbra::testing
