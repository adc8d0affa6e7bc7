// CityEngine's initial shape as a ground face (ground_face.h).
#include "runtime/cga/ground_face.h"

#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fgsg::rt::cga {
namespace {

// Snapping to exact 0 / 1 keeps a rectangle's corners exact.
double normalised(double c, double lo, double size) {
  if (!(size > 0.0)) return 0.0;
  const double t = (c - lo) / size;
  constexpr double kSnap = 1e-12;
  return std::abs(t) < kSnap ? 0.0 : std::abs(t - 1.0) < kSnap ? 1.0 : t;
}

// Whether the edge a -> b runs along the ring `outline`.
bool groundEdgeOnOutline(const Polygon3& outline, const Vec3& a, const Vec3& b) {
  for (size_t j = 0; j < outline.size(); ++j)
    if (outline[j] == a && outline[(j + 1) % outline.size()] == b) return true;
  return false;
}

// The first edge with a length on the outline (a lot with a courtyard is one ring whose
// bridges to the courtyard, and the courtyard's own edges, may come first): its index,
// and in `along` its direction across `up` (not normalised). -1: none.
long groundFirstOutlineEdge(const std::vector<Vec3>& world, const Vec3& up, Vec3& along) {
  const std::vector<Polygon3> rings = ringsOf(world);
  for (size_t i = 0; i < world.size(); ++i) {
    const Vec3& a = world[i];
    const Vec3& b = world[(i + 1) % world.size()];
    if (rings.size() > 1 && !groundEdgeOnOutline(rings[0], a, b)) continue;
    along = (b - a) - (b - a).dot(up) * up;
    if (along.norm() >= 1e-12) return static_cast<long>(i);
  }
  return -1;
}

}  // namespace

bool isGroundFace(const GeomRef& geom, const GeometryArena& arena) {
  if (geom.kind != GeomKind::Polyhedron || geom.count != 1) return false;
  const GeometryArena::Face& f = arena.face(geom, 0);
  const Vec3* pts = arena.facePoints(f);
  for (uint32_t i = 0; i < f.count; ++i)
    if (pts[i].y() != 0.0) return false;
  return f.count >= 3;
}

void polygonOnGround(Scope& scope, GeomRef& geom, GeometryArena& arena, const Vec3* xAxis) {
  if (geom.kind != GeomKind::Polygon || geom.count < 3) return;
  std::vector<Vec3> world;
  world.reserve(geom.count);
  for (uint32_t i = 0; i < geom.count; ++i)
    world.push_back(scope.toWorld(scope.S.cwiseProduct(arena.polygon(geom)[i])));
  const Vec3 up = scope.Z();
  Vec3 x = Vec3::Zero();
  if (xAxis) x = *xAxis - xAxis->dot(up) * up;
  if (x.norm() < 1e-12) groundFirstOutlineEdge(world, up, x);
  if (x.norm() < 1e-12) return;
  x.normalize();
  const Vec3 z = x.cross(up);
  const Vec3& origin = world.front();
  double umin = std::numeric_limits<double>::infinity(), wmin = umin, umax = -umin, wmax = -umin;
  for (const Vec3& p : world) {
    const double u = (p - origin).dot(x), w = (p - origin).dot(z);
    umin = std::min(umin, u), umax = std::max(umax, u);
    wmin = std::min(wmin, w), wmax = std::max(wmax, w);
  }
  Scope out = scope;
  out.axes.col(0) = x;
  out.axes.col(1) = up;
  out.axes.col(2) = z;
  out.P = origin + x * umin + z * wmin;
  out.S = Vec3(umax - umin, 0.0, wmax - wmin);
  Polygon3 face;
  face.reserve(world.size());
  for (const Vec3& p : world)
    face.emplace_back(normalised((p - origin).dot(x), umin, out.S.x()), 0.0,
                      normalised((p - origin).dot(z), wmin, out.S.z()));
  // Counter-clockwise seen from above (+y), as a solid's top face.
  if (newellNormal(face).y() < 0) std::reverse(face.begin(), face.end());
  scope = out;
  geom = arena.addPolyhedron({face});
}

void groundToPolygon(Scope& scope, GeomRef& geom, GeometryArena& arena) {
  if (!isGroundFace(geom, arena)) return;
  const GeometryArena::Face& f = arena.face(geom, 0);
  const Vec3* pts = arena.facePoints(f);
  std::vector<Vec3> poly;
  poly.reserve(f.count);
  for (uint32_t i = 0; i < f.count; ++i) poly.emplace_back(pts[i].x(), 1.0 - pts[i].z(), 0.0);
  if (newellNormal(poly).z() < 0) std::reverse(poly.begin(), poly.end());
  Scope out = scope;
  out.axes.col(0) = scope.X();
  out.axes.col(1) = -scope.Z();
  out.axes.col(2) = scope.Y();
  out.P = scope.P + scope.Z() * scope.S.z();
  out.S = Vec3(scope.S.x(), scope.S.z(), 0.0);
  scope = out;
  geom = arena.addPolygon(poly);
}

Scope initialShapeFrame(const Scope& scope, const GeomRef& geom, const GeometryArena& arena) {
  Scope frame;
  frame.P = scope.P;
  frame.axes = scope.axes;
  if (geom.kind != GeomKind::Polygon || geom.count < 3) return frame;
  std::vector<Vec3> world;
  world.reserve(geom.count);
  for (uint32_t i = 0; i < geom.count; ++i) world.push_back(scope.toWorld(scope.S.cwiseProduct(arena.polygon(geom)[i])));
  const Vec3 up = scope.Z();
  Vec3 x;
  const long edge = groundFirstOutlineEdge(world, up, x);
  if (edge < 0) return frame;
  x.normalize();
  frame.P = world[static_cast<size_t>(edge)];
  frame.axes.col(0) = x;
  frame.axes.col(1) = up;
  frame.axes.col(2) = x.cross(up);
  return frame;
}

}  // namespace fgsg::rt::cga
