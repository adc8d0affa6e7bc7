#include "runtime/cga/trim_planes.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::cga {

namespace {

// CityEngine's classification angle (attr_trim): an edge within 40 degrees of the pivot's
// xz plane makes a horizontal plane.
constexpr double kTrimHorizontalDegrees = 40.0;

bool trimSamePoint(const Vec3& p, const Vec3& q, double tol) { return (p - q).norm() <= tol; }

// A plane seen in the normalised coordinates u of a scope (world p = P + axes (S . u)):
// d(u) = along . u + offset, d the world distance to the plane (positive: cut off).
struct TrimLocalPlane {
  Vec3 along;
  double offset;
  double at(const Vec3& u) const { return along.dot(u) + offset; }
};

// Sutherland-Hodgman: the part of `face` where d <= tol (points on the plane kept).
Polygon3 trimClipFace(const Polygon3& face, const TrimLocalPlane& plane, double tol) {
  Polygon3 out;
  const size_t n = face.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = face[i];
    const Vec3& b = face[(i + 1) % n];
    const double da = plane.at(a), db = plane.at(b);
    if (da <= tol) out.push_back(a);
    if ((da < -tol && db > tol) || (da > tol && db < -tol)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// A face's area in world units (the scope's scale applied, its position left out).
double trimWorldArea(const Scope& scope, const Polygon3& face) {
  Polygon3 world;
  for (const Vec3& u : face) world.push_back(scope.axes * scope.S.cwiseProduct(u));
  return 0.5 * newellNormal(world).norm();
}

// The cap of a solid cut by `plane`: the kept faces' edges that lie on the plane, those two
// faces share taken out, reversed and chained into loops (one cap face each). False when
// they do not close into loops (the solid is then left open there).
bool trimCaps(const Scope& scope, const std::vector<Polygon3>& kept, const TrimLocalPlane& plane, double tol,
              std::vector<Polygon3>& caps) {
  struct Segment {
    Vec3 a, b;
    bool used = false;
  };
  std::vector<Segment> segments;
  auto world = [&](const Vec3& u) -> Vec3 { return scope.axes * scope.S.cwiseProduct(u); };
  for (const Polygon3& face : kept)
    for (size_t i = 0; i < face.size(); ++i) {
      const Vec3& a = face[i];
      const Vec3& b = face[(i + 1) % face.size()];
      if (std::abs(plane.at(a)) > tol || std::abs(plane.at(b)) > tol || trimSamePoint(world(a), world(b), tol))
        continue;
      // An edge two kept faces walk both ways is inside the kept part: it borders no cap.
      auto twin = std::find_if(segments.begin(), segments.end(), [&](const Segment& s) {
        return !s.used && trimSamePoint(world(s.a), world(a), tol) && trimSamePoint(world(s.b), world(b), tol);
      });
      if (twin != segments.end()) {
        twin->used = true;
        continue;
      }
      segments.push_back({b, a});  // the cap walks the edge the other way
    }
  segments.erase(std::remove_if(segments.begin(), segments.end(), [](const Segment& s) { return s.used; }),
                 segments.end());
  for (size_t start = 0; start < segments.size(); ++start) {
    if (segments[start].used) continue;
    Polygon3 loop{segments[start].a};
    segments[start].used = true;
    Vec3 end = segments[start].b;
    while (!trimSamePoint(world(end), world(loop.front()), tol)) {
      auto next = std::find_if(segments.begin(), segments.end(),
                               [&](const Segment& s) { return !s.used && trimSamePoint(world(s.a), world(end), tol); });
      if (next == segments.end()) return false;
      next->used = true;
      loop.push_back(next->a);
      end = next->b;
    }
    if (loop.size() >= 3 && trimWorldArea(scope, loop) > kMinArea) caps.push_back(std::move(loop));
  }
  return true;
}

}  // namespace

std::vector<std::vector<TrimPlane>> faceTrimPlanes(const std::vector<Polygon3>& faces,
                                                   const std::vector<Vec3>& normals, const Vec3& up, double tol) {
  std::vector<std::vector<TrimPlane>> planes(faces.size());
  const double horizontalSine = std::sin(kTrimHorizontalDegrees * M_PI / 180.0);
  for (size_t i = 0; i < faces.size(); ++i) {
    const Polygon3& f = faces[i];
    for (size_t k = 0; k < f.size(); ++k) {
      const Vec3& a = f[k];
      const Vec3& b = f[(k + 1) % f.size()];
      if (trimSamePoint(a, b, tol)) continue;
      int neighbour = -1, found = 0;
      for (size_t j = 0; j < faces.size(); ++j) {
        if (j == i) continue;
        const Polygon3& g = faces[j];
        for (size_t m = 0; m < g.size(); ++m) {
          const Vec3& c = g[m];
          const Vec3& d = g[(m + 1) % g.size()];
          if ((trimSamePoint(c, b, tol) && trimSamePoint(d, a, tol)) ||
              (trimSamePoint(c, a, tol) && trimSamePoint(d, b, tol)))
            neighbour = static_cast<int>(j), ++found;
        }
      }
      if (found != 1) continue;  // a border edge, or one more than two faces meet at
      Vec3 between = normals[size_t(neighbour)] - normals[i];
      if (between.norm() < 1e-6 || normals[i].dot(normals[size_t(neighbour)]) < -1.0 + 1e-9) continue;
      const Vec3 along = (b - a).normalized();
      // The face (inward from its counter-clockwise edge: normal x edge) stays on the kept
      // side: at a concave edge (an L-shaped building's inner corner) the difference of the
      // normals points back over the face, and the plane keeps the other side.
      if (normals[i].cross(along).dot(between) > 0) between = -between;
      planes[i].push_back({a, between.normalized(), std::abs(along.dot(up.normalized())) < horizontalSine});
    }
  }
  return planes;
}

std::vector<std::vector<TrimPlane>> compTrimPlanes(const Scope& scope, const GeomRef& geom,
                                                   const GeometryArena& arena, const std::vector<Part>& parts,
                                                   const Vec3& up) {
  std::vector<std::vector<TrimPlane>> out(parts.size());
  if (geom.kind != GeomKind::Box && geom.kind != GeomKind::Polyhedron) return out;  // one face or none: no edges shared
  // The shape's faces in world points with their outward normals (a box's from its axes,
  // so a flat box keeps oriented faces, as components() has them).
  auto world = [&](const Vec3& u) { return scope.toWorld(scope.S.cwiseProduct(u)); };
  std::vector<Polygon3> faces;
  std::vector<Vec3> normals;
  const std::vector<Polygon3> local = geom.kind == GeomKind::Box ? unitBoxFaces() : loadGeometry(arena, geom).faces;
  const Vec3 boxNormals[6] = {scope.Z(), scope.X(), -scope.Z(), -scope.X(), scope.Y(), -scope.Y()};
  for (size_t i = 0; i < local.size(); ++i) {
    Polygon3 f;
    for (const Vec3& u : local[i]) f.push_back(world(u));
    const Vec3 n = geom.kind == GeomKind::Box ? boxNormals[i] : newellNormal(f);
    if (n.norm() <= 1e-12 * (1.0 + scope.S.squaredNorm())) continue;  // no orientation: no planes
    faces.push_back(std::move(f));
    normals.push_back(n.normalized());
  }
  const double tol = 1e-9 * (1.0 + scope.S.norm());
  const std::vector<std::vector<TrimPlane>> perFace = faceTrimPlanes(faces, normals, up, tol);
  // A face part has the face's corners in order, in its own scope (components.cpp facePart).
  for (size_t p = 0; p < parts.size(); ++p) {
    const Part& part = parts[p];
    if (part.geom.kind != GeomKind::Polygon) continue;
    const Vec3* pts = arena.polygon(part.geom);
    const Vec3 first = part.scope.toWorld(part.scope.S.cwiseProduct(pts[0]));
    for (size_t i = 0; i < faces.size(); ++i)
      if (faces[i].size() == part.geom.count && normals[i].dot(part.scope.Z()) > 1.0 - 1e-9 &&
          trimSamePoint(faces[i].front(), first, 1e3 * tol)) {
        out[p] = perFace[i];
        break;
      }
  }
  return out;
}

bool trimGeometry(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const std::vector<TrimPlane>& planes,
                  Part& out) {
  out = Part{scope, geom, false, 0};
  if (planes.empty() || geom.kind == GeomKind::Edge) return false;
  LocalGeometry g;
  if (geom.kind == GeomKind::Box) {
    g.kind = GeomKind::Polyhedron;
    g.faces = unitBoxFaces();
  } else {
    g = loadGeometry(arena, geom);
  }
  const bool solid = g.kind == GeomKind::Polyhedron;
  const double tol = 1e-9 * (1.0 + scope.S.norm());
  bool changed = false;
  for (const TrimPlane& p : planes) {
    const TrimLocalPlane plane{scope.S.cwiseProduct(scope.axes.transpose() * p.normal), p.normal.dot(scope.P - p.point)};
    double most = -INFINITY;
    for (const Polygon3& face : g.faces)
      for (const Vec3& u : face) most = std::max(most, plane.at(u));
    if (most <= tol) continue;  // all of it on the kept side
    changed = true;
    std::vector<Polygon3> kept;
    for (const Polygon3& face : g.faces) {
      Polygon3 clipped = trimClipFace(face, plane, tol);
      if (clipped.size() >= 3 && trimWorldArea(scope, clipped) > kMinArea) kept.push_back(std::move(clipped));
    }
    if (solid && !kept.empty()) {
      std::vector<Polygon3> caps;
      if (trimCaps(scope, kept, plane, 100 * tol, caps)) kept.insert(kept.end(), caps.begin(), caps.end());
    }
    g.faces = std::move(kept);
    if (g.faces.empty()) break;
  }
  if (!changed) return false;
  if (g.faces.empty()) {
    out.geom = arena.addPolyhedron({});
    return true;
  }
  out.geom = storeGeometry(arena, g);
  return false;
}

}  // namespace fgsg::rt::cga
