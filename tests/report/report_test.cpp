// The report's figures, pictures and page, on small hand-made views.
#include "penumbra/report/report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cost_chart.hpp"
#include "html_page.hpp"
#include "penumbra/report/figures.hpp"
#include "pixel_font.hpp"
#include "shading.hpp"

namespace penumbra::report {
namespace {

using reference::Surface;

// A 4x1 view: ground, ground, a box side, the background.
reference::StageView four_pixels() {
  reference::StageView view;
  view.receivers = FloatImage(4, 1, 3);
  view.surfaces = {Surface::ground, Surface::top, Surface::side, Surface::none};
  view.points.resize(4);
  return view;
}

FloatImage row(std::initializer_list<float> values) {
  FloatImage image(int(values.size()), 1, 1);
  image.data = values;
  return image;
}

TEST(Figures, MeasureOnlyLitFacesAndNameTheirTruth) {
  const auto view = four_pixels();
  // Pixel 0 is in the penumbra (exact 0.5), pixel 1 fully lit; the side and
  // the background are wrong by 1 but not measured.
  const FloatImage exact = row({0.5f, 1.0f, 1.0f, 1.0f});
  const FloatImage visibility = row({0.25f, 0.875f, 0.0f, 0.0f});
  const FloatImage reference = row({0.25f, 1.0f, 0.0f, 1.0f});
  const FloatImage reads = row({4.0f, 8.0f, 100.0f, 100.0f});
  const Figures f = measure(view, exact, visibility, reference, row({0, 0, 0, 0}), reads);
  EXPECT_DOUBLE_EQ(f.exact_penumbra_mae, 0.25);
  EXPECT_DOUBLE_EQ(f.exact_penumbra_rmse, 0.25);
  EXPECT_DOUBLE_EQ(f.exact_penumbra_max, 0.25);
  EXPECT_DOUBLE_EQ(f.exact_max, 0.25);
  EXPECT_DOUBLE_EQ(f.exact_rmse, std::sqrt((0.25 * 0.25 + 0.125 * 0.125) / 2));
  EXPECT_DOUBLE_EQ(f.reference_mae, 0.0625);
  EXPECT_DOUBLE_EQ(f.reference_max, 0.125);
  EXPECT_DOUBLE_EQ(f.texel_reads_per_pixel, 6.0);
  EXPECT_DOUBLE_EQ(f.texel_reads_max, 8.0);
  const Region r = region(view, exact);
  EXPECT_EQ(r.measured, 2u);
  EXPECT_EQ(r.penumbra, 1u);
  const nlohmann::json json = to_json(f);
  EXPECT_EQ(json.at("exact_penumbra_mae"), 0.25);
  EXPECT_EQ(json.at("reference_max"), 0.125);
}

TEST(Figures, ANanIsTheLargestError) {
  const auto view = four_pixels();
  const FloatImage exact = row({0.5f, 1.0f, 1.0f, 1.0f});
  const FloatImage visibility = row({NAN, 1.0f, 1.0f, 1.0f});
  const Figures f = measure(view, exact, visibility, exact, row({0, 0, 0, 0}), row({0, 0, 0, 0}));
  EXPECT_TRUE(std::isinf(f.exact_penumbra_max));
  EXPECT_TRUE(std::isinf(f.reference_max));
}

// Where the reference is undecided (a receiver_plane quad across a depth
// step), the run is not held to it, as verify does not; exact still counts.
TEST(Figures, PixelsTheReferenceLeavesUndecidedAreNotComparedToIt) {
  const auto view = four_pixels();
  const FloatImage exact = row({0.5f, 1.0f, 1.0f, 1.0f});
  const FloatImage visibility = row({0.5f, 0.0f, 1.0f, 1.0f});
  const FloatImage reference = row({0.5f, 1.0f, 1.0f, 1.0f});
  const Figures f =
      measure(view, exact, visibility, reference, row({0, 1, 0, 0}), row({0, 0, 0, 0}));
  EXPECT_DOUBLE_EQ(f.reference_max, 0.0);
  EXPECT_DOUBLE_EQ(f.reference_mae, 0.0);
  EXPECT_DOUBLE_EQ(f.exact_max, 1.0);
}

TEST(Pictures, ShadowIsDarkerThanLightAndHeatmapsRiseWithError) {
  const auto view = four_pixels();
  const Picture lit = shade(view, row({1.0f, 1.0f, 1.0f, 1.0f}));
  const Picture dark = shade(view, row({0.0f, 0.0f, 0.0f, 0.0f}));
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(lit.rgb[c], dark.rgb[c]);          // the ground
    EXPECT_GT(lit.rgb[3 + c], dark.rgb[3 + c]);  // a box top
    EXPECT_EQ(lit.rgb[6 + c], dark.rgb[6 + c]);  // a side: the light grazes it
  }
  const auto brightness = [](const Picture& p, int pixel) {
    return p.rgb[3 * pixel] + p.rgb[3 * pixel + 1] + p.rgb[3 * pixel + 2];
  };
  const FloatImage zero = row({0.0f, 0.0f, 0.0f, 0.0f});
  const Picture none = heatmap(view, zero, zero);
  const Picture some = heatmap(view, row({0.05f, 0.1f, 0.0f, 0.0f}), zero);
  const Picture full = heatmap(view, row({kHeatmapFullScale, 1.0f, 0.0f, 0.0f}), zero);
  EXPECT_EQ(brightness(none, 0), 0);
  EXPECT_GT(brightness(some, 1), brightness(some, 0));
  EXPECT_GT(brightness(full, 0), brightness(some, 1));
  EXPECT_EQ(brightness(full, 0), brightness(full, 1));  // saturated at the full scale
}

TEST(Pictures, CropScalesAndPanelsSitSideBySide) {
  Picture p(3, 2);
  p.set(1, 0, {1.0f, 0.0f, 0.0f});
  const Picture crop = crop_scaled(p, {1, 0, 2, 2}, 2);
  ASSERT_EQ(crop.width, 4);
  ASSERT_EQ(crop.height, 4);
  EXPECT_EQ(crop.rgb[0], 255);            // (0, 0) is p's (1, 0)
  EXPECT_EQ(crop.rgb[3 * (4 + 1)], 255);  // so is (1, 1)
  EXPECT_EQ(crop.rgb[3 * 2], 0);          // (2, 0) is p's (2, 0)
  const Picture sheet = side_by_side({crop, crop}, 3);
  EXPECT_EQ(sheet.width, 11);
  EXPECT_EQ(sheet.rgb[3 * 7], 255);  // the second panel starts at x = 7
}

TEST(Page, EmbedsTheReportSoThatNoStringEndsTheScript) {
  const nlohmann::json report = {{"generator", "penumbra test"},
                                 {"rows", {{{"variant", "</script><b>x"}}}}};
  const std::string page = html_page(report, "<svg id=\"cost-chart\"></svg>");
  EXPECT_EQ(page.find("{{PENUMBRA_REPORT_DATA}}"), std::string::npos);
  EXPECT_EQ(page.find("{{PENUMBRA_COST_CHART}}"), std::string::npos);
  EXPECT_NE(page.find("<svg id=\"cost-chart\"></svg>"), std::string::npos);
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
  EXPECT_NE(page.find("<\\/script><b>x"), std::string::npos);
  // No asset from elsewhere: every reference stays in the report's folder.
  EXPECT_EQ(page.find("http"), std::string::npos);
}

// Four variants: b is beaten by a (cheaper and closer) on time, d is the
// most exact; on reads c is cheapest.
std::vector<CostPoint> four_costs() {
  return {{"a", "pcf_grid", 1.0, 36.0, 0.05},
          {"b", "pcf_grid", 2.0, 40.0, 0.06},
          {"c", "pcss", 3.0, 20.0, 0.04},
          {"d", "bitmask_backprojection", 9.0, 90.0, 0.01}};
}

TEST(CostChart, ParetoFrontIsWhatNothingBeatsOnBothCostAndError) {
  const auto points = four_costs();
  EXPECT_EQ(pareto_front(points, CostAxis::gpu_ms), (std::vector<std::size_t>{0, 2, 3}));
  EXPECT_EQ(pareto_front(points, CostAxis::texel_reads), (std::vector<std::size_t>{2, 3}));
  EXPECT_TRUE(pareto_front({}, CostAxis::gpu_ms).empty());
}

TEST(CostChart, SvgHasAPointPerVariantPerPanelTheFrontAndTheLabels) {
  const std::string svg = cost_chart_svg(four_costs());
  const auto count = [&](const std::string& text) {
    std::size_t n = 0;
    for (std::size_t at = svg.find(text); at != std::string::npos; at = svg.find(text, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(svg.rfind("<svg id=\"cost-chart\"", 0), 0u);
  EXPECT_EQ(count("<g class=\"panel\""), 2u);
  EXPECT_EQ(count("<circle class=\"point"), 8u);
  EXPECT_EQ(count("<circle class=\"point pareto\""), 5u);  // 3 on time, 2 on reads
  EXPECT_EQ(count("<polyline class=\"pareto-front\""), 2u);
  EXPECT_EQ(count("<text class=\"point-label\""), 5u);
  EXPECT_EQ(count("<text class=\"technique-label\""), 3u);
  for (const char* technique : {"pcf_grid", "pcss", "bitmask_backprojection"}) {
    EXPECT_NE(svg.find(std::string(">") + technique + "</text>"), std::string::npos) << technique;
  }
}

TEST(CostChart, PictureIsDrawnWithEveryTechniquesColour) {
  const Picture chart = cost_chart_picture(four_costs());
  ASSERT_GT(chart.width, 0);
  std::size_t white = 0, orange = 0;
  for (std::size_t i = 0; i < chart.rgb.size(); i += 3) {
    const auto r = chart.rgb[i], g = chart.rgb[i + 1], b = chart.rgb[i + 2];
    white += r == 255 && g == 255 && b == 255;
    orange += r == 0xf2 && g == 0x8e && b == 0x2b;  // the second technique's colour
  }
  EXPECT_GT(white, chart.rgb.size() / 6);  // mostly background
  EXPECT_GT(orange, 20u);                  // pcss's points and legend swatch
}

TEST(PixelFont, LabelsAThumbnailOnADarkBand) {
  Picture thumb(60, 30);
  for (auto& byte : thumb.rgb) byte = 128;
  const Picture out = labelled(thumb, "pcss_k1");
  std::size_t lit = 0;
  for (int y = 0; y < 13; ++y) {
    for (int x = 0; x < out.width; ++x) lit += out.rgb[(std::size_t(y) * out.width + x) * 3] == 255;
  }
  EXPECT_GT(lit, 30u);                          // the letters
  EXPECT_EQ(out.rgb[(20 * 60 + 30) * 3], 128);  // below the band, the picture
  EXPECT_EQ(text_width("abc"), 17);
}

TEST(ReportDirectory, OnlyAReportOrNothingMayBeReplaced) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "penumbra-report-dir";
  fs::remove_all(dir);
  EXPECT_TRUE(check_report_directory(dir).ok());  // missing
  fs::create_directories(dir);
  EXPECT_TRUE(check_report_directory(dir).ok());  // empty
  std::ofstream(dir / "notes.txt") << "mine";
  const Status refused = check_report_directory(dir);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().kind, Error::Kind::bad_input);
  EXPECT_NE(refused.error().to_string().find("not a penumbra report"), std::string::npos);
  std::ofstream(dir / "report.json") << R"({"generator": "penumbra 0.1.0"})";
  EXPECT_TRUE(check_report_directory(dir).ok());
  fs::remove_all(dir);
  std::ofstream(dir.string()) << "a file";
  EXPECT_FALSE(check_report_directory(dir).ok());
  fs::remove(dir);
}

}  // namespace
}  // namespace penumbra::report
