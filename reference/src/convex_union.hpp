// The area of a union of convex polygons, exactly (up to rounding): the
// measure exact_visibility() takes of the occluders' shadows on the light.
#pragma once

#include <vector>

namespace penumbra::reference {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

// A convex polygon: its vertices in order around it (either way round).
using ConvexPolygon = std::vector<Point2>;

// The convex hull of `points`, counter-clockwise; fewer than 3 vertices when
// the points span no area.
ConvexPolygon convex_hull(std::vector<Point2> points);

// `polygon` clipped to the square [-half, half]^2 (empty when outside it).
ConvexPolygon clip_to_square(const ConvexPolygon& polygon, double half);

// The area of the union of `polygons`.
double union_area(const std::vector<ConvexPolygon>& polygons);

}  // namespace penumbra::reference
