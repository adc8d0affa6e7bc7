// CityEngine's splitArea: a split along a scope axis whose sizes are areas. Each cut is the
// plane across the axis that leaves the part before it with the area asked for; the areas
// are laid out as a `.cga` split lays out lengths (cityEngineSizes), on the shape's area.
#include "runtime/cga/axis_names.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {
namespace {

// The area of the part of `face` whose coordinate along `dir` (from `origin`) is at most
// `t`: the polygon clipped by one plane (Sutherland-Hodgman), measured by Newell's normal.
// A concave face cut into several pieces comes back joined by zero-width bridges, which
// add no area.
double areaBelow(const Polygon3& face, const Vec3& origin, const Vec3& dir, double t) {
  Polygon3 kept;
  const size_t n = face.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = face[i];
    const Vec3& b = face[(i + 1) % n];
    const double ua = (a - origin).dot(dir) - t, ub = (b - origin).dot(dir) - t;
    if (ua <= 0) kept.push_back(a);
    if ((ua < 0 && ub > 0) || (ua > 0 && ub < 0)) kept.push_back(a + (b - a) * (ua / (ua - ub)));
  }
  return kept.size() < 3 ? 0.0 : 0.5 * newellNormal(kept).norm();
}

}  // namespace

bool splitAreaSizes(const Scope& scope, const GeomRef& geom, const GeometryArena& arena, int axis, bool repeat,
                    const std::vector<SizeValue>& areas, std::vector<SizeValue>& lengths, std::vector<bool>& derived,
                    std::string& error) {
  const std::vector<std::vector<Vec3>> faces = surfacePolygons(scope, geom, arena);
  if (faces.size() != 1) {
    error = "splitArea: splits a flat shape (a lot, a face, a footprint), not a solid or an edge: comp(f) first";
    return false;
  }
  const double length = scope.S[axis];
  if (!(length > 0)) {
    error = std::string("splitArea along ") + kAxisNames[axis] + ": the scope has no size along it";
    return false;
  }
  const Polygon3& face = faces[0];
  const Vec3 dir = scope.axes.col(axis).normalized();
  const double total = 0.5 * newellNormal(face).norm();
  if (!(total > 0)) {
    error = "splitArea: the shape has no area";
    return false;
  }
  // A relative area ('x in a .cga file, xr in fgsg's) is that share of the shape's area.
  std::vector<SizeValue> written = areas;
  for (SizeValue& s : written)
    if (s.kind == SizeValue::Relative) s = {SizeValue::Absolute, s.value * total};
  std::vector<SizeValue> partAreas;
  size_t pattern = 0;
  if (!cityEngineSizes(written, total, axis, repeat, partAreas, derived, pattern, error)) {
    error = "splitArea: " + error;
    return false;
  }
  // Each cut where the area before it reaches the parts' areas so far: the area grows
  // monotonically with the cut's position, so bisection finds it (to 1e-12 of the scope).
  lengths.clear();
  double reached = 0.0, at = 0.0;
  const double tiny = 1e-12 * total;
  for (size_t k = 0; k < partAreas.size(); ++k) {
    reached += partAreas[k].value;
    double cut = length;
    if (k + 1 < partAreas.size() && reached < total - tiny) {
      double lo = at, hi = length;
      for (int step = 0; step < 200 && hi - lo > 1e-12 * length; ++step) {
        const double mid = 0.5 * (lo + hi);
        (areaBelow(face, scope.P, dir, mid) < reached ? lo : hi) = mid;
      }
      cut = 0.5 * (lo + hi);
    }
    lengths.push_back({SizeValue::Absolute, cut - at});
    at = cut;
  }
  return true;
}

}  // namespace fgsg::rt::cga
