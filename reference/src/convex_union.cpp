// Union area by vertical slabs: cut the plane at every vertex and every
// crossing of two edges. Inside one slab no edge ends or crosses another, so
// each polygon's section is one interval whose ends move linearly with x,
// and the length of the union of the intervals is linear in x: its value at
// the slab's middle times the slab's width is the slab's exact area.
#include "convex_union.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::reference {
namespace {

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Where segments ab and cd cross, when they do at one point.
bool crossing_x(const Point2& a, const Point2& b, const Point2& c, const Point2& d, double& x) {
  const double denom = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
  if (denom == 0.0) return false;
  const double t = ((c.x - a.x) * (d.y - c.y) - (c.y - a.y) * (d.x - c.x)) / denom;
  const double s = ((c.x - a.x) * (b.y - a.y) - (c.y - a.y) * (b.x - a.x)) / denom;
  if (t < 0.0 || t > 1.0 || s < 0.0 || s > 1.0) return false;
  x = a.x + t * (b.x - a.x);
  return true;
}

struct Interval {
  double low, high;
};

// The section of a convex polygon at x, when the line x = const meets its inside.
bool section(const ConvexPolygon& p, double x, Interval& out) {
  double low = INFINITY, high = -INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % p.size()];
    if (a.x == b.x || x < std::min(a.x, b.x) || x > std::max(a.x, b.x)) continue;
    const double y = a.y + (x - a.x) / (b.x - a.x) * (b.y - a.y);
    low = std::min(low, y);
    high = std::max(high, y);
  }
  out = {low, high};
  return low < high;
}

double union_length(std::vector<Interval>& intervals) {
  std::sort(intervals.begin(), intervals.end(),
            [](const Interval& a, const Interval& b) { return a.low < b.low; });
  double length = 0.0, start = -INFINITY, end = -INFINITY;
  for (const Interval& i : intervals) {
    if (i.low > end) {
      if (end > start) length += end - start;
      start = i.low;
      end = i.high;
    } else {
      end = std::max(end, i.high);
    }
  }
  if (end > start) length += end - start;
  return length;
}

}  // namespace

ConvexPolygon convex_hull(std::vector<Point2> points) {
  // Andrew's monotone chain.
  std::sort(points.begin(), points.end(), [](const Point2& a, const Point2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  if (points.size() < 3) return points;
  ConvexPolygon hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

ConvexPolygon clip_to_square(const ConvexPolygon& polygon, double half) {
  // Sutherland-Hodgman against each of the four half-planes.
  ConvexPolygon out = polygon;
  for (int edge = 0; edge < 4 && !out.empty(); ++edge) {
    const auto inside_by = [&](const Point2& p) {
      const double v = edge < 2 ? p.x : p.y;
      return edge % 2 == 0 ? half - v : v + half;  // >= 0 inside
    };
    ConvexPolygon in = std::move(out);
    out.clear();
    for (std::size_t i = 0; i < in.size(); ++i) {
      const Point2& a = in[i];
      const Point2& b = in[(i + 1) % in.size()];
      const double da = inside_by(a), db = inside_by(b);
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) {
        const double t = da / (da - db);
        Point2 p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        // On the square's edge by construction: exactly there, so that a
        // shadow covering the whole light has exactly its area.
        (edge < 2 ? p.x : p.y) = edge % 2 == 0 ? half : -half;
        out.push_back(p);
      }
    }
  }
  return out.size() >= 3 ? out : ConvexPolygon{};
}

double union_area(const std::vector<ConvexPolygon>& polygons) {
  std::vector<double> xs;
  for (const ConvexPolygon& p : polygons) {
    for (const Point2& v : p) xs.push_back(v.x);
  }
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    for (std::size_t j = i + 1; j < polygons.size(); ++j) {
      const ConvexPolygon& p = polygons[i];
      const ConvexPolygon& q = polygons[j];
      for (std::size_t a = 0; a < p.size(); ++a) {
        for (std::size_t c = 0; c < q.size(); ++c) {
          double x = 0.0;
          if (crossing_x(p[a], p[(a + 1) % p.size()], q[c], q[(c + 1) % q.size()], x)) {
            xs.push_back(x);
          }
        }
      }
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  double area = 0.0;
  std::vector<Interval> sections;
  for (std::size_t s = 0; s + 1 < xs.size(); ++s) {
    const double middle = (xs[s] + xs[s + 1]) / 2;
    sections.clear();
    for (const ConvexPolygon& p : polygons) {
      Interval i{};
      if (section(p, middle, i)) sections.push_back(i);
    }
    area += union_length(sections) * (xs[s + 1] - xs[s]);
  }
  return area;
}

}  // namespace penumbra::reference
