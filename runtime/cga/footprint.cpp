// Footprint: a shape becomes a polygon lot on the ground.
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/skeleton_roof.h"
#include "runtime/planar.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {
namespace {

std::string pointText(const Vec2& p) {
  std::ostringstream m;
  m << "(" << p.x() << ", " << p.y() << ")";
  return m.str();
}

}  // namespace

// The polygon scope stands on the ground: X kept, Z up (the old Y: the polygon's
// normal), Y = Z x X, which runs against the old Z; its origin is the corner of the
// bounding box at (xmin, zmax), so a corner (x, z) lies at normalised
// ((x - xmin) / w, (zmax - z) / d). Extrude and Roof then stand solids on it Y-up.
bool footprint(const Scope& scope, const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
               GeometryArena& arena, Part& out, std::string& error) {
  std::vector<Vec2> corners;
  for (size_t i = 0; i < outer.size(); ++i) {
    const Vec2& p = outer[i];
    if (!p.allFinite()) {
      error = "Footprint: corner " + std::to_string(i + 1) + " is not a finite point";
      return false;
    }
    if (corners.empty() || p != corners.back()) corners.push_back(p);
  }
  if (corners.size() > 1 && corners.front() == corners.back()) corners.pop_back();  // a closed ring
  if (corners.size() < 3) {
    error = "Footprint: a polygon needs three different corners, got " + std::to_string(corners.size());
    return false;
  }
  const size_t n = corners.size();
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share a corner
      if (segmentsMeet(corners[i], corners[(i + 1) % n], corners[j], corners[(j + 1) % n])) {
        error = "Footprint: the polygon crosses itself: the edge from corner " + std::to_string(i + 1) + " " +
                pointText(corners[i]) + " meets the edge from corner " + std::to_string(j + 1) + " " +
                pointText(corners[j]);
        return false;
      }
    }
  // A courtyard: the holes joined to the outline by zero-width bridges, which Extrude,
  // Roof and the splits understand (bridgeEdges, ringsOf).
  if (!holes.empty() && !joinHoles(corners, holes, "Footprint: ", corners, error)) return false;
  Vec2 lo = corners[0], hi = corners[0];
  for (const Vec2& p : corners) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double w = hi.x() - lo.x(), d = hi.y() - lo.y();
  Polygon3 polygon;
  for (const Vec2& p : corners) polygon.emplace_back((p.x() - lo.x()) / w, (hi.y() - p.y()) / d, 0.0);
  const double normal = newellNormal(polygon).z();
  if (!(w > 0 && d > 0) || !(std::abs(normal) > 1e-12)) {
    error = "Footprint: the polygon has no area";
    return false;
  }
  if (normal < 0) std::reverse(polygon.begin(), polygon.end());  // counter-clockwise seen from above

  out = Part{};
  out.scope = scope;
  out.scope.axes.col(0) = scope.X();
  out.scope.axes.col(1) = -scope.Z();
  out.scope.axes.col(2) = scope.Y();
  out.scope.P = scope.toWorld(Vec3(lo.x(), 0.0, hi.y()));
  out.scope.S = Vec3(w, d, 0.0);
  out.geom = arena.addPolygon(polygon);
  return true;
}

}  // namespace fgsg::rt::cga
