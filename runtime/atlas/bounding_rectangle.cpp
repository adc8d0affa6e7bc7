#include "runtime/atlas/bounding_rectangle.h"

#include "runtime/atlas/uv_geometry.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::atlas {

std::vector<Vec2> convexHull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {  // lower chain
    while (k >= 2 && twiceSignedArea(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && twiceSignedArea(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

double minimalRectangleAngle(const std::vector<Vec2>& points) {
  const std::vector<Vec2> hull = convexHull(points);
  const size_t h = hull.size();
  if (h < 3) return 0;
  // Each hull edge as a side of the rectangle in turn. Hulls of charts have tens to a few
  // hundred points, so the quadratic scan costs less than anything else done per chart.
  double bestArea = INFINITY, bestAngle = 0;
  for (size_t i = 0; i < h; ++i) {
    const Vec2 e = (hull[(i + 1) % h] - hull[i]).normalized();
    const Vec2 n(-e.y(), e.x());
    double lo = INFINITY, hi = -INFINITY, height = 0;
    for (const Vec2& p : hull) {
      const double a = e.dot(p - hull[i]);
      lo = std::min(lo, a), hi = std::max(hi, a);
      height = std::max(height, n.dot(p - hull[i]));
    }
    const double area = (hi - lo) * height;
    if (area < bestArea) {
      bestArea = area;
      bestAngle = -std::atan2(e.y(), e.x());
    }
  }
  return bestAngle;
}

}  // namespace fgsg::rt::atlas
