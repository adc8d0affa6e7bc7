// CityEngine's taper(height): a pyramid over the polygon, its apex `height` above the
// polygon's centre of gravity along its normal. The solid's frame is extrude's (x kept as
// far as it lies in the polygon's plane, y along the normal, z completing it), so the
// scope fits the pyramid: the polygon's box, sy = height.
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {

bool taper(const Scope& scope, const GeomRef& geom, double height, GeometryArena& arena, Part& out,
           std::string& error) {
  if (!(height > 0.0) || !std::isfinite(height)) {
    std::ostringstream m;
    m << "taper: the height " << height << " must be positive (a downward taper is not supported)";
    error = m.str();
    return false;
  }
  const bool solidBox = geom.kind == GeomKind::Box && scope.S.minCoeff() > 0.0;
  if ((geom.kind == GeomKind::Polyhedron && !lyingOnGround(geom, arena)) || solidBox) {
    error = "taper: expects a polygon (a lot, a Footprint, a Comp face) or a flat footprint, got a solid";
    return false;
  }
  // The prism extrude builds has the polygon as its base (y = 0 in its frame) and its top
  // at y = 1; a rectangle comes back as a box.
  Part prism;
  if (!extrude(scope, geom, height, arena, prism, error)) {
    error = "taper: " + error;
    return false;
  }
  Polygon3 base;
  if (prism.geom.kind == GeomKind::Polyhedron) {
    const GeometryArena::Face& top = arena.face(prism.geom, prism.geom.count - 2);
    base.assign(arena.facePoints(top), arena.facePoints(top) + top.count);
    for (Vec3& p : base) p.y() = 0.0;
  } else {
    base = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
  }
  if (newellNormal(base).y() < 0) std::reverse(base.begin(), base.end());
  // The centre of gravity of the polygon's area (the frame is affine to the world's, so the
  // centroid in frame coordinates is the world's centroid).
  double twiceArea = 0.0, cx = 0.0, cz = 0.0;
  for (size_t i = 0; i < base.size(); ++i) {
    const Vec3& a = base[i];
    const Vec3& b = base[(i + 1) % base.size()];
    const double w = a.z() * b.x() - a.x() * b.z();  // twice the signed area of (0, a, b) seen from +y
    twiceArea += w;
    cx += (a.x() + b.x()) * w;
    cz += (a.z() + b.z()) * w;
  }
  if (!(std::abs(twiceArea) > 0.0)) {
    error = "taper: the polygon has no area";
    return false;
  }
  const Vec3 apex(cx / (3.0 * twiceArea), 1.0, cz / (3.0 * twiceArea));
  std::vector<Polygon3> faces;
  const std::vector<bool> bridge = bridgeEdges(base);
  for (size_t i = 0; i < base.size(); ++i)
    if (!bridge[i]) faces.push_back({base[i], base[(i + 1) % base.size()], apex});
  faces.emplace_back(base.rbegin(), base.rend());
  out = Part{};
  out.scope = prism.scope;
  out.geom = arena.addPolyhedron(faces);
  return true;
}

}  // namespace fgsg::rt::cga
