// geometry.*() of CityEngine's CGA on a shape's own geometry (geometry_queries.h).
#include "runtime/cga/geometry_queries.h"

#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace fgsg::rt::cga {
namespace {

// Relative to the scope's size: corners closer than this are one vertex.
constexpr double kQueryMergeTol = 1e-9;

// Every face of the geometry in world space: what geometry.* measure.
std::vector<Polygon3> worldPolygons(const Scope& scope, const GeomRef& geom, const GeometryArena& arena) {
  std::vector<Polygon3> out;
  if (geom.kind == GeomKind::Edge) return out;
  auto toWorld = [&](const Vec3& n) { return scope.toWorld(scope.S.cwiseProduct(n)); };
  if (geom.kind == GeomKind::Box) {
    const double tol = kQueryMergeTol * (1.0 + scope.S.norm());
    int flatAxis = -1, flats = 0;
    for (int a = 0; a < 3; ++a)
      if (!(scope.S[a] > tol)) flatAxis = a, ++flats;
    if (flats > 1) return out;  // a line or a point
    // unitBoxFaces: front (+Z), right (+X), back, left, top (+Y), bottom. A flat box is
    // its one face looking along the axis it has no size in.
    const std::vector<Polygon3>& box = unitBoxFaces();
    for (size_t i = 0; i < box.size(); ++i) {
      if (flatAxis >= 0 && i != (flatAxis == 0 ? 1u : flatAxis == 1 ? 4u : 0u)) continue;
      Polygon3 f;
      for (const Vec3& p : box[i]) f.push_back(toWorld(p));
      out.push_back(std::move(f));
    }
    return out;
  }
  for (const Polygon3& local : loadGeometry(arena, geom).faces) {
    Polygon3 f;
    for (const Vec3& p : local) f.push_back(toWorld(p));
    out.push_back(std::move(f));
  }
  return out;
}

// Vertex ids with corners closer than `tol` merged.
class Vertices {
 public:
  explicit Vertices(double tol) : tol_(tol) {}
  int id(const Vec3& p) {
    for (size_t k = 0; k < points_.size(); ++k)
      if ((points_[k] - p).cwiseAbs().maxCoeff() <= tol_) return int(k);
    points_.push_back(p);
    return int(points_.size() - 1);
  }
  const std::vector<Vec3>& points() const { return points_; }

 private:
  double tol_;
  std::vector<Vec3> points_;
};

// A ring with a corner that turns against its normal (beyond rounding).
bool hasReflexCorner(const Polygon3& ring, const Vec3& normal, double tol) {
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = ring[(i + n - 1) % n];
    const Vec3& b = ring[i];
    const Vec3& c = ring[(i + 1) % n];
    if ((b - a).cross(c - b).dot(normal) < -tol) return true;
  }
  return false;
}

}  // namespace

GeometryFacts geometryFacts(const Scope& scope, const GeomRef& geom, const GeometryArena& arena) {
  GeometryFacts facts;
  const std::vector<Polygon3> faces = worldPolygons(scope, geom, arena);
  const double size = 1.0 + scope.S.norm();
  Vertices vertices(kQueryMergeTol * size);
  std::map<std::pair<int, int>, std::pair<int, double>> edges;  // (lo, hi) -> (faces, length)
  for (const Polygon3& f : faces) {
    const Vec3 newell = newellNormal(f);
    facts.area += 0.5 * newell.norm();
    ++facts.faces;
    if (newell.norm() > 0) {
      const Vec3 n = newell.normalized();
      const std::vector<Polygon3> rings = ringsOf(f);
      facts.concave = facts.concave || rings.size() > 1 || hasReflexCorner(rings.front(), n, 1e-12 * size * size);
    }
    for (size_t i = 0; i < f.size(); ++i) {
      const int a = vertices.id(f[i]), b = vertices.id(f[(i + 1) % f.size()]);
      if (a == b) continue;
      auto& e = edges[{std::min(a, b), std::max(a, b)}];
      ++e.first;
      e.second = (f[i] - f[(i + 1) % f.size()]).norm();
    }
  }
  facts.vertices = int(vertices.points().size());
  // A courtyard's bridge is run both ways by its one face: not boundary.
  for (const auto& [key, e] : edges)
    if (e.first == 1) facts.boundaryLength += e.second;
  if (!vertices.points().empty()) {
    double lo = vertices.points().front().y(), hi = lo;
    for (const Vec3& p : vertices.points()) lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
    facts.height = hi - lo;
  }
  return facts;
}

bool geometryIsPlanar(const Scope& scope, const GeomRef& geom, const GeometryArena& arena, double toleranceDegrees) {
  const std::vector<Polygon3> faces = worldPolygons(scope, geom, arena);
  Vec3 normal = Vec3::Zero(), origin = Vec3::Zero();
  for (const Polygon3& f : faces) {
    const Vec3 n = newellNormal(f);
    if (n.norm() > 0) {
      normal = n.normalized();
      origin = f.front();
      break;
    }
  }
  if (normal.isZero()) return false;
  const double tol = std::max(0.0, toleranceDegrees) * 3.14159265358979323846 / 180.0;
  const double cosTol = std::cos(tol);
  const double reach = kQueryMergeTol * (1.0 + scope.S.norm()) + scope.S.norm() * std::sin(std::min(tol, 1.5707963267948966));
  for (const Polygon3& f : faces) {
    const Vec3 n = newellNormal(f);
    if (n.norm() > 0 && n.normalized().dot(normal) < cosTol - 1e-12) return false;
    for (const Vec3& p : f)
      if (std::abs((p - origin).dot(normal)) > reach) return false;
  }
  return true;
}

double geometryAngle(const Scope& scope, const GeomRef& geom, const GeometryArena& arena, GeometryAngleKind kind) {
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  constexpr double kAngleTieDegrees = 1e-9;
  double steepest = -1.0;  // degrees
  Vec3 facing = Vec3::Zero();
  for (const Polygon3& f : worldPolygons(scope, geom, arena)) {
    const Vec3 n = newellNormal(f);
    if (!(n.norm() > 0)) continue;
    // atan2 keeps the angle exact near level and upright faces, where acos loses digits.
    const double slope = std::atan2(std::hypot(n.x(), n.z()), std::abs(n.y())) * kDegrees;
    if (slope > steepest + kAngleTieDegrees) steepest = slope, facing = n;  // rounding: the first of equals
  }
  const double maxSlope = std::max(steepest, 0.0);
  switch (kind) {
    case GeometryAngleKind::MaxSlope: return maxSlope;
    case GeometryAngleKind::Zenith: return 90.0 - maxSlope;
    case GeometryAngleKind::Azimuth: break;
  }
  if (!(steepest > kAngleTieDegrees)) return 0.0;  // level: no direction
  // North is -z, east +x: clockwise seen from above.
  double azimuth = std::atan2(facing.x(), -facing.z()) * kDegrees;
  if (azimuth < 0.0) azimuth += 360.0;
  return azimuth >= 360.0 - kAngleTieDegrees ? 0.0 : azimuth;  // a hair west of north is north
}

std::vector<std::vector<Vec3>> geometryWorldFaces(const Scope& scope, const GeomRef& geom, const GeometryArena& arena) {
  return worldPolygons(scope, geom, arena);
}

std::array<double, 2> geometryUvSpread(const Scope& scope, const GeomRef& geom, const GeometryArena& arena,
                                       const UvProjection& projection) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const Polygon3& f : worldPolygons(scope, geom, arena)) {
    const Vec3 facing = newellNormal(f);
    for (const Vec3& p : f) {
      const std::array<double, 2> uv = projectPoint(projection, p, facing);
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], uv[k]), hi[k] = std::max(hi[k], uv[k]);
    }
  }
  if (!(hi[0] >= lo[0])) return {0.0, 0.0};
  return {hi[0] - lo[0], hi[1] - lo[1]};
}

}  // namespace fgsg::rt::cga
