// Extrude: grows a footprint (a flat box or a polygon) into a solid.
#include "runtime/cga/cga.h"
#include "runtime/cga/ground_face.h"
#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {

// A box keeps its scope and gets sy = height (any box: it is re-extruded from its base).
// A polygon becomes a prism whose scope stands on the polygon (solidFrameOnPolygon: Y is
// the polygon's normal, so buildings on polygon footprints are Y-up like box buildings);
// its faces are the sides in the polygon's edge order (none along a courtyard's bridge),
// then the top, then the bottom. A `.cga` lot (a ground face, ground_face.h) is the base
// of its prism in its own scope. A unit-square polygon (a rectangular lot) gives a Box,
// which is the same solid, with no arena use.
bool extrude(const Scope& scope, const GeomRef& geom, double height, GeometryArena& arena,
             Part& out, std::string& error) {
  if (!(height > 0.0) || !std::isfinite(height)) {
    std::ostringstream m;
    m << "Extrude: the height " << height << " must be positive";
    error = m.str();
    return false;
  }
  out = Part{};
  if (geom.kind == GeomKind::Box) {
    out.scope = scope;
    out.scope.S.y() = height;
    return true;
  }
  Polygon3 base;
  if (isGroundFace(geom, arena)) {
    // A `.cga` lot already lies in its solid's frame: its face is the base as it is
    // (through fgsg's polygon frame each corner would be rounded twice, 1 - (1 - z)).
    out.scope = scope;
    const GeometryArena::Face& f = arena.face(geom, 0);
    base.assign(arena.facePoints(f), arena.facePoints(f) + f.count);
    if (newellNormal(base).y() < 0) {
      // A lot turned over (reverseNormals) faces down, and CityEngine extrudes along the
      // face's normal: the prism hangs below it, its scope turned half round x (y down).
      out.scope.axes.col(1) = -scope.axes.col(1);
      out.scope.axes.col(2) = -scope.axes.col(2);
      out.scope.P = scope.P + scope.axes.col(2) * scope.S.z();
      for (Vec3& p : base) p.z() = 1.0 - p.z();
    }
    out.scope.S.y() = height;
    Polygon3 square;  // a rectangle is a Box, as a unit-square polygon is
    for (const Vec3& p : base) square.emplace_back(p.x(), 1.0 - p.z(), 0.0);
    if (isUnitSquare(square.data(), square.size())) {
      out.geom = GeomRef{};
      return true;
    }
  } else if (geom.kind != GeomKind::Polygon) {
    error = "Extrude: expects a polygon or a flat box (a footprint), got a solid or an edge";
    return false;
  } else {
    out.scope = solidFrameOnPolygon(scope);
    out.scope.S.y() = height;
    if (isUnitSquare(arena.polygon(geom), geom.count)) return true;

    // Polygon (x, y) lies at (x, 0, 1 - y) of the solid's frame (see solidFrameOnPolygon).
    const bool flat = scope.S.y() <= 0.0;
    base.reserve(geom.count);
    for (uint32_t i = 0; i < geom.count; ++i) {
      const Vec3& p = arena.polygon(geom)[i];
      base.emplace_back(p.x(), 0.0, flat ? 0.0 : 1.0 - p.y());
    }
  }
  // The polygon is counter-clockwise about its normal (+Y here); repair a clockwise one
  // so the solid is not inside out.
  if (newellNormal(base).y() < 0) std::reverse(base.begin(), base.end());

  const std::size_t n = base.size();
  std::vector<Polygon3> faces;
  faces.reserve(n + 2);
  Polygon3 top = base;
  for (Vec3& p : top) p.y() = 1.0;
  // A courtyard's bridge (an edge run both ways) is no wall: its two faces would be one
  // wall seen from both sides, inside the solid.
  const std::vector<bool> bridge = bridgeEdges(base);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (!bridge[i]) faces.push_back({base[i], base[j], top[j], top[i]});
  }
  Polygon3 bottom(base.rbegin(), base.rend());
  faces.push_back(std::move(top));
  faces.push_back(std::move(bottom));
  out.geom = arena.addPolyhedron(faces);
  return true;
}

}  // namespace fgsg::rt::cga
