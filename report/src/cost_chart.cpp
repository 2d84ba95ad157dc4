#include "cost_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <string_view>

#include "pixel_font.hpp"

namespace penumbra::report {
namespace {

// One layout for both renderings, in pixels.
constexpr int kPanelWidth = 580;
constexpr int kLegendTop = 410;
constexpr int kChartWidth = 2 * kPanelWidth;
constexpr int kChartHeight = 460;
constexpr int kPlotLeft = 70;  // within a panel
constexpr int kPlotRight = 550;
constexpr int kPlotTop = 40;
constexpr int kPlotBottom = 350;
constexpr int kPointRadius = 4;

// Tableau's ten colours (sRGB), one per technique in order of appearance.
constexpr std::uint32_t kPalette[] = {0x4e79a7, 0xf28e2b, 0xe15759, 0x76b7b2, 0x59a14f,
                                      0xedc948, 0xb07aa1, 0xff9da7, 0x9c755f, 0xbab0ac};
constexpr std::uint32_t kInk = 0x1b1d21;
constexpr std::uint32_t kGrid = 0xdddddd;
constexpr std::uint32_t kFront = 0x1b1d21;
constexpr std::uint32_t kLeader = 0xaaaaaa;

std::string hex(std::uint32_t colour) {
  char text[8];
  std::snprintf(text, sizeof text, "#%06x", colour);
  return text;
}

Rgb linear(std::uint32_t colour) {
  const auto channel = [](std::uint32_t c) {
    const double s = double(c & 0xff) / 255.0;
    return float(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
  };
  return {channel(colour >> 16), channel(colour >> 8), channel(colour)};
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string escaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// 1, 2 or 5 times a power of ten, at least `value`.
double nice_step(double value) {
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * decade >= value * (1.0 - 1e-9)) return m * decade;
  }
  return 10.0 * decade;
}

struct Tick {
  double value;
  int at;  // pixel
};

// A panel's scales: cost on a log axis of whole decades, error linear from 0.
struct Panel {
  CostAxis axis;
  int left;  // the panel's left edge in the chart
  double lo = 1.0, hi = 10.0, top = 0.1, step = 0.02;

  Panel(CostAxis a, int panel_left, const std::vector<CostPoint>& points)
      : axis(a), left(panel_left) {
    double least = INFINITY, most = 0.0, worst = 0.0;
    for (const CostPoint& p : points) {
      const double c = cost_of(p, axis);
      if (c > 0.0) least = std::min(least, c);
      most = std::max(most, c);
      if (std::isfinite(p.mae)) worst = std::max(worst, p.mae);
    }
    if (std::isfinite(least) && most > 0.0) {
      lo = std::pow(10.0, std::floor(std::log10(least)));
      hi = std::max(lo * 10.0, std::pow(10.0, std::ceil(std::log10(most))));
    }
    step = nice_step(std::max(worst * 1.05, 1e-3) / 5.0);
    top = std::max(step, std::ceil(worst * 1.05 / step) * step);
  }

  int x(double cost) const {
    const double t =
        (std::log10(std::clamp(cost, lo, hi)) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
    return left + kPlotLeft + int(std::lround(t * (kPlotRight - kPlotLeft)));
  }
  int y(double mae) const {
    const double v = std::isfinite(mae) ? std::clamp(mae, 0.0, top) : top;
    return kPlotBottom - int(std::lround(v / top * (kPlotBottom - kPlotTop)));
  }
  std::vector<Tick> x_ticks() const {
    std::vector<Tick> ticks;
    for (double decade = lo; decade <= hi * 1.001; decade *= 10.0) {
      for (double m : {1.0, 2.0, 5.0}) {
        if (m * decade <= hi * 1.001) ticks.push_back({m * decade, x(m * decade)});
      }
    }
    return ticks;
  }
  std::vector<Tick> y_ticks() const {
    std::vector<Tick> ticks;
    for (int i = 0; i * step <= top * (1.0 + 1e-9); ++i) ticks.push_back({i * step, y(i * step)});
    return ticks;
  }
  std::string title() const {
    return axis == CostAxis::gpu_ms ? "error against GPU time" : "error against texel reads";
  }
  std::string x_title() const {
    return axis == CostAxis::gpu_ms ? "GPU ms: depth + mip + query (median, timestamp queries)"
                                    : "texel reads per pixel";
  }
};

// Each technique's colour, in order of first appearance.
std::vector<std::pair<std::string, std::uint32_t>> technique_colours(
    const std::vector<CostPoint>& points) {
  std::vector<std::pair<std::string, std::uint32_t>> colours;
  for (const CostPoint& p : points) {
    const bool known = std::any_of(colours.begin(), colours.end(),
                                   [&](const auto& c) { return c.first == p.technique; });
    if (!known) {
      colours.emplace_back(p.technique, kPalette[colours.size() % std::size(kPalette)]);
    }
  }
  return colours;
}

std::uint32_t colour_of(const std::vector<std::pair<std::string, std::uint32_t>>& colours,
                        const std::string& technique) {
  for (const auto& [name, colour] : colours) {
    if (name == technique) return colour;
  }
  return kInk;
}

// The legend's entries: where each swatch goes, wrapping at the chart's width.
struct LegendEntry {
  std::string technique;
  std::uint32_t colour;
  int x, y;
};
std::vector<LegendEntry> legend(const std::vector<std::pair<std::string, std::uint32_t>>& colours) {
  std::vector<LegendEntry> entries;
  int x = kPlotLeft, y = kLegendTop + 10;
  for (const auto& [name, colour] : colours) {
    const int width = 20 + text_width(name) + 24;
    if (x + width > kChartWidth - 20) {
      x = kPlotLeft;
      y += 18;
    }
    entries.push_back({name, colour, x, y});
    x += width;
  }
  return entries;
}

// Raster primitives on a Picture.
void fill(Picture& p, int x0, int y0, int x1, int y1, Rgb c) {
  for (int y = std::max(0, y0); y < std::min(p.height, y1); ++y) {
    for (int x = std::max(0, x0); x < std::min(p.width, x1); ++x) p.set(x, y, c);
  }
}

void line(Picture& p, int x0, int y0, int x1, int y1, Rgb c, int thickness) {
  const int steps = std::max({std::abs(x1 - x0), std::abs(y1 - y0), 1});
  const int half = thickness / 2;
  for (int i = 0; i <= steps; ++i) {
    const int x = x0 + int(std::lround(double(x1 - x0) * i / steps));
    const int y = y0 + int(std::lround(double(y1 - y0) * i / steps));
    fill(p, x - half, y - half, x - half + thickness, y - half + thickness, c);
  }
}

void disc(Picture& p, int cx, int cy, double radius, Rgb c) {
  const int r = int(std::ceil(radius));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy <= radius * radius)
        fill(p, cx + dx, cy + dy, cx + dx + 1, cy + dy + 1, c);
    }
  }
}

// Where each front point's label goes (its box's top-left corner, in
// pixels), so that labels of nearby points do not overlap: above right of
// the point if free (of other labels and of the front's points), else to
// its left, else moved up or down a line at a time; `moved` labels get a
// leader line to their point.
struct LabelPlace {
  std::size_t point;
  int x, top, width;
  bool moved;
};
std::vector<LabelPlace> place_labels(const Panel& panel, const std::vector<CostPoint>& points,
                                     const std::vector<std::size_t>& front) {
  constexpr int kLine = kGlyphHeight + 3;
  struct Box {
    int x, top, width, height;
  };
  // The front's points are in the way too.
  std::vector<Box> taken;
  for (std::size_t i : front) {
    taken.push_back(
        {panel.x(cost_of(points[i], panel.axis)) - 6, panel.y(points[i].mae) - 6, 12, 12});
  }
  const auto fits = [&](const Box& b) {
    if (b.x < panel.left + 4 || b.x + b.width > panel.left + kPanelWidth - 4 ||
        b.top < kPlotTop - 8 || b.top + b.height > kPlotBottom) {
      return false;
    }
    return std::none_of(taken.begin(), taken.end(), [&](const Box& o) {
      return b.x < o.x + o.width + 3 && o.x < b.x + b.width + 3 && b.top < o.top + o.height &&
             o.top < b.top + b.height;
    });
  };
  std::vector<LabelPlace> placed;
  for (std::size_t i : front) {
    const int x = panel.x(cost_of(points[i], panel.axis)), y = panel.y(points[i].mae);
    const int width = text_width(points[i].variant);
    LabelPlace place{i, x + 8, y - 12, width, false};
    bool found = false;
    for (int step = 0; step <= 24 && !found; ++step) {
      const int dy = (step + 1) / 2 * kLine * (step % 2 ? 1 : -1);
      for (int left : {x + 8, x - 8 - width}) {
        if (!found && fits({left, y - 12 + dy, width, kLine})) {
          place = {i, left, y - 12 + dy, width, left < x || dy != 0};
          found = true;
        }
      }
    }
    taken.push_back({place.x, place.top, width, kLine});
    placed.push_back(place);
  }
  return placed;
}

void draw_panel(Picture& pic, const Panel& panel, const std::vector<CostPoint>& points,
                const std::vector<std::pair<std::string, std::uint32_t>>& colours) {
  const Rgb ink = linear(kInk), grid = linear(kGrid);
  const int l = panel.left + kPlotLeft, r = panel.left + kPlotRight;
  draw_text(pic, panel.left + kPlotLeft, 8, panel.title(), ink, 2);
  draw_text(pic, panel.left + 8, kPlotTop - 14, "exact_penumbra_mae", ink);
  for (const Tick& t : panel.y_ticks()) {
    line(pic, l, t.at, r, t.at, grid, 1);
    const std::string label = number(t.value);
    draw_text(pic, l - 6 - text_width(label), t.at - 3, label, ink);
  }
  for (const Tick& t : panel.x_ticks()) {
    line(pic, t.at, kPlotTop, t.at, kPlotBottom, grid, 1);
    const std::string label = number(t.value);
    draw_text(pic, t.at - text_width(label) / 2, kPlotBottom + 6, label, ink);
  }
  line(pic, l, kPlotBottom, r, kPlotBottom, ink, 1);
  line(pic, l, kPlotTop, l, kPlotBottom, ink, 1);
  const std::string x_title = panel.x_title();
  draw_text(pic, (l + r - text_width(x_title)) / 2, kPlotBottom + 24, x_title, ink);

  const std::vector<std::size_t> front = pareto_front(points, panel.axis);
  for (std::size_t i = 1; i < front.size(); ++i) {
    const CostPoint &a = points[front[i - 1]], &b = points[front[i]];
    line(pic, panel.x(cost_of(a, panel.axis)), panel.y(a.mae), panel.x(cost_of(b, panel.axis)),
         panel.y(b.mae), linear(kFront), 2);
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
    const int x = panel.x(cost_of(points[i], panel.axis)), y = panel.y(points[i].mae);
    if (on_front) disc(pic, x, y, kPointRadius + 2, linear(kFront));
    disc(pic, x, y, kPointRadius, linear(colour_of(colours, points[i].technique)));
  }
  for (const LabelPlace& label : place_labels(panel, points, front)) {
    const CostPoint& p = points[label.point];
    if (label.moved) {
      line(pic, panel.x(cost_of(p, panel.axis)), panel.y(p.mae),
           label.x < panel.x(cost_of(p, panel.axis)) ? label.x + label.width : label.x - 2,
           label.top + 4, linear(kLeader), 1);
    }
    draw_text(pic, label.x, label.top, p.variant, ink);
  }
}

void svg_panel(std::string& svg, const Panel& panel, const std::vector<CostPoint>& points,
               const std::vector<std::pair<std::string, std::uint32_t>>& colours) {
  const int l = panel.left + kPlotLeft, r = panel.left + kPlotRight;
  const auto at = [](int x, int y) {
    return "x=\"" + std::to_string(x) + "\" y=\"" + std::to_string(y) + "\"";
  };
  svg += "<g class=\"panel\" data-axis=\"" +
         std::string(panel.axis == CostAxis::gpu_ms ? "gpu_ms" : "texel_reads") + "\">\n";
  svg += "<text class=\"panel-title\" " + at(l, 22) + " font-size=\"15\" font-weight=\"bold\">" +
         panel.title() + "</text>\n";
  svg += "<text " + at(panel.left + 8, kPlotTop - 8) + ">exact_penumbra_mae</text>\n";
  for (const Tick& t : panel.y_ticks()) {
    svg += "<line x1=\"" + std::to_string(l) + "\" x2=\"" + std::to_string(r) + "\" y1=\"" +
           std::to_string(t.at) + "\" y2=\"" + std::to_string(t.at) + "\" stroke=\"" + hex(kGrid) +
           "\"/>\n";
    svg += "<text " + at(l - 6, t.at + 4) + " text-anchor=\"end\">" + number(t.value) + "</text>\n";
  }
  for (const Tick& t : panel.x_ticks()) {
    svg += "<line x1=\"" + std::to_string(t.at) + "\" x2=\"" + std::to_string(t.at) + "\" y1=\"" +
           std::to_string(kPlotTop) + "\" y2=\"" + std::to_string(kPlotBottom) + "\" stroke=\"" +
           hex(kGrid) + "\"/>\n";
    svg += "<text " + at(t.at, kPlotBottom + 16) + " text-anchor=\"middle\">" + number(t.value) +
           "</text>\n";
  }
  svg += "<polyline fill=\"none\" stroke=\"" + hex(kInk) + "\" points=\"" + std::to_string(l) +
         "," + std::to_string(kPlotTop) + " " + std::to_string(l) + "," +
         std::to_string(kPlotBottom) + " " + std::to_string(r) + "," + std::to_string(kPlotBottom) +
         "\"/>\n";
  svg += "<text " + at((l + r) / 2, kPlotBottom + 34) + " text-anchor=\"middle\">" +
         escaped(panel.x_title()) + "</text>\n";

  const std::vector<std::size_t> front = pareto_front(points, panel.axis);
  svg += "<polyline class=\"pareto-front\" fill=\"none\" stroke=\"" + hex(kFront) +
         "\" stroke-width=\"2\" points=\"";
  for (std::size_t i : front) {
    svg += std::to_string(panel.x(cost_of(points[i], panel.axis))) + "," +
           std::to_string(panel.y(points[i].mae)) + " ";
  }
  svg += "\"/>\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CostPoint& p = points[i];
    const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
    svg += "<circle class=\"point" + std::string(on_front ? " pareto" : "") + "\" data-variant=\"" +
           escaped(p.variant) + "\" data-technique=\"" + escaped(p.technique) + "\" cx=\"" +
           std::to_string(panel.x(cost_of(p, panel.axis))) + "\" cy=\"" +
           std::to_string(panel.y(p.mae)) + "\" r=\"" + std::to_string(kPointRadius) +
           "\" fill=\"" + hex(colour_of(colours, p.technique)) + "\"" +
           (on_front ? " stroke=\"" + hex(kFront) + "\" stroke-width=\"2\"" : "") + "><title>" +
           escaped(p.variant) + " (" + escaped(p.technique) +
           "): " + number(cost_of(p, panel.axis)) +
           (panel.axis == CostAxis::gpu_ms ? " ms" : " reads/px") + ", exact_penumbra_mae " +
           number(p.mae) + "</title></circle>\n";
  }
  for (const LabelPlace& label : place_labels(panel, points, front)) {
    const CostPoint& p = points[label.point];
    const int x = panel.x(cost_of(p, panel.axis)), y = panel.y(p.mae);
    if (label.moved) {
      svg += "<line class=\"leader\" x1=\"" + std::to_string(x) + "\" y1=\"" + std::to_string(y) +
             "\" x2=\"" + std::to_string(label.x < x ? label.x + label.width : label.x - 2) +
             "\" y2=\"" + std::to_string(label.top + 4) + "\" stroke=\"" + hex(kLeader) + "\"/>\n";
    }
    svg += "<text class=\"point-label\" " + at(label.x, label.top + 8) + ">" + escaped(p.variant) +
           "</text>\n";
  }
  svg += "</g>\n";
}

}  // namespace

double cost_of(const CostPoint& point, CostAxis axis) {
  return axis == CostAxis::gpu_ms ? point.gpu_ms : point.texel_reads;
}

std::vector<std::size_t> pareto_front(const std::vector<CostPoint>& points, CostAxis axis) {
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  // By cost, then error, then library order: a point is on the front when
  // its error is below that of every point before it.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double ca = cost_of(points[a], axis), cb = cost_of(points[b], axis);
    return ca != cb ? ca < cb : points[a].mae < points[b].mae;
  });
  std::vector<std::size_t> front;
  double best = INFINITY;
  for (std::size_t i : order) {
    if (points[i].mae < best) {
      front.push_back(i);
      best = points[i].mae;
    }
  }
  return front;
}

std::string cost_chart_svg(const std::vector<CostPoint>& points) {
  const auto colours = technique_colours(points);
  std::string svg = "<svg id=\"cost-chart\" width=\"" + std::to_string(kChartWidth) +
                    "\" height=\"" + std::to_string(kChartHeight) + "\" viewBox=\"0 0 " +
                    std::to_string(kChartWidth) + " " + std::to_string(kChartHeight) +
                    "\" role=\"img\" aria-label=\"exact_penumbra_mae against GPU time and "
                    "texel reads per variant\" font-family=\"sans-serif\" font-size=\"11\" "
                    "fill=\"" +
                    hex(kInk) + "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  for (CostAxis axis : {CostAxis::gpu_ms, CostAxis::texel_reads}) {
    svg_panel(svg, Panel(axis, axis == CostAxis::gpu_ms ? 0 : kPanelWidth, points), points,
              colours);
  }
  svg += "<g class=\"legend\">\n";
  for (const LegendEntry& e : legend(colours)) {
    svg += "<circle cx=\"" + std::to_string(e.x + 6) + "\" cy=\"" + std::to_string(e.y + 3) +
           "\" r=\"" + std::to_string(kPointRadius + 1) + "\" fill=\"" + hex(e.colour) +
           "\"/><text class=\"technique-label\" x=\"" + std::to_string(e.x + 16) + "\" y=\"" +
           std::to_string(e.y + 7) + "\">" + escaped(e.technique) + "</text>\n";
  }
  if (points.empty()) {
    svg +=
        "<text x=\"" + std::to_string(kPlotLeft) + "\" y=\"" + std::to_string(kLegendTop + 14) +
        "\">no variant was timed (no spirv runs, or a device without timestamp queries)</text>\n";
  }
  return svg + "</g>\n</svg>\n";
}

Picture cost_chart_picture(const std::vector<CostPoint>& points) {
  Picture pic(kChartWidth, kChartHeight);
  fill(pic, 0, 0, kChartWidth, kChartHeight, {1.0f, 1.0f, 1.0f});
  const auto colours = technique_colours(points);
  for (CostAxis axis : {CostAxis::gpu_ms, CostAxis::texel_reads}) {
    draw_panel(pic, Panel(axis, axis == CostAxis::gpu_ms ? 0 : kPanelWidth, points), points,
               colours);
  }
  for (const LegendEntry& e : legend(colours)) {
    disc(pic, e.x + 6, e.y + 3, kPointRadius + 1, linear(e.colour));
    draw_text(pic, e.x + 16, e.y, e.technique, linear(kInk));
  }
  if (points.empty()) {
    draw_text(pic, kPlotLeft, kLegendTop + 8, "no variant was timed", linear(kInk));
  }
  return pic;
}

}  // namespace penumbra::report
