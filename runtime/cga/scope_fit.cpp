// Scope operations (rotateScope, alignScopeToAxes, alignScopeToGeometry, mirrorScope) and
// the geometry operations that keep the scope (mirror, reverseNormals, deleteHoles,
// cleanupGeometry): the geometry is taken to world coordinates, the new scope fitted
// around it, and the geometry stored again in the new scope's unit box.
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>

namespace fgsg::rt::cga {
namespace {

struct WorldGeometry {
  GeomKind kind = GeomKind::Polygon;
  std::vector<Polygon3> faces;  // world points, each face as stored (outward / counter-clockwise)
  bool box = false;             // the scope box itself
};

bool worldGeometry(const Scope& s, const GeomRef& g, const GeometryArena& arena, const char* what,
                   WorldGeometry& out, std::string& error) {
  auto world = [&](const Vec3& u) -> Vec3 { return s.P + s.axes * s.S.cwiseProduct(u); };
  out = WorldGeometry{};
  if (g.kind == GeomKind::Edge) {
    error = std::string(what) + ": expects a face or a solid, not an edge";
    return false;
  }
  if (g.kind == GeomKind::Box) {
    int zero = -1, zeros = 0;
    for (int k = 0; k < 3; ++k)
      if (!(s.S[k] > 0.0)) zero = k, ++zeros;
    if (zeros == 0) {
      out.kind = GeomKind::Polyhedron;
      out.box = true;
      for (const Polygon3& f : unitBoxFaces()) {
        out.faces.emplace_back();
        for (const Vec3& u : f) out.faces.back().push_back(world(u));
      }
      return true;
    }
    if (zeros > 1) {
      error = std::string(what) + ": the shape has no area (two of its scope sizes are zero)";
      return false;
    }
    // A flat box (a footprint S(w, 0, d), a facade piece): its one face, counter-clockwise
    // about the axis it has no size in.
    const int i = (zero + 1) % 3, j = (zero + 2) % 3;
    Polygon3 face;
    for (const auto& [a, b] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}) {
      Vec3 u = Vec3::Zero();
      u[i] = a, u[j] = b;
      face.push_back(world(u));
    }
    out.kind = GeomKind::Polygon;
    out.faces.push_back(face);
    return true;
  }
  const LocalGeometry local = loadGeometry(arena, g);
  out.kind = g.kind;
  for (const Polygon3& f : local.faces) {
    out.faces.emplace_back();
    for (const Vec3& u : f) out.faces.back().push_back(world(u));
  }
  return true;
}

Vec3 faceNormal(const Polygon3& f) { return newellNormal(f); }  // length: twice the area

// The least rotation that turns unit vector a onto unit vector b.
Mat3 rotationOnto(const Vec3& a, const Vec3& b) {
  return Eigen::Quaterniond::FromTwoVectors(a, b).toRotationMatrix();
}

// fgsg's polygon frame: the axis nearest the polygon's normal renamed Z, the frame kept
// right-handed (Y the normal: X kept, Y = -Z, as Footprint turns a box's frame; X the
// normal: the axes named cyclically), then the least rotation laying Z on the normal.
Mat3 polygonFrame(const Mat3& axes, const Vec3& normal) {
  const Vec3 n = normal.normalized();
  int k = 0;
  for (int c = 1; c < 3; ++c)
    if (std::abs(axes.col(c).dot(n)) > std::abs(axes.col(k).dot(n))) k = c;
  Mat3 a = axes;
  if (k == 1) a.col(1) = -axes.col(2), a.col(2) = axes.col(1);
  if (k == 0) a.col(0) = axes.col(1), a.col(1) = axes.col(2), a.col(2) = axes.col(0);
  if (a.col(2).dot(n) < 0) a.col(1) = -a.col(1), a.col(2) = -a.col(2);
  return rotationOnto(a.col(2), n) * a;
}

bool signedPermutationOf(const Mat3& a, const Mat3& b) {
  for (int c = 0; c < 3; ++c) {
    bool found = false;
    for (int d = 0; d < 3; ++d) found |= std::abs(std::abs(a.col(c).dot(b.col(d))) - 1.0) < 1e-12;
    if (!found) return false;
  }
  return true;
}

// The shape with scope axes `axes` fitted around the geometry.
void fit(const Scope& base, const Mat3& axes, const WorldGeometry& g, GeometryArena& arena, Part& out) {
  out = Part{};
  std::vector<Polygon3> faces = fitScopeAroundWorldFaces(base, axes, g.faces, out.scope);
  if (g.box && signedPermutationOf(axes, base.axes)) {
    out.geom = GeomRef{};  // still the scope box
    return;
  }
  // A one-face solid that lies in the new scope's XY plane is fgsg's polygon again.
  bool inPlane = g.kind == GeomKind::Polyhedron && faces.size() == 1 && !(out.scope.S.z() > 0);
  if (inPlane && !(out.scope.S.y() > 0)) inPlane = false;  // lying on the ground (XZ): a ground face
  if (g.kind == GeomKind::Polygon || inPlane) {
    Polygon3& p = faces[0];
    for (Vec3& q : p) q.z() = 0.0;
    if (newellNormal(p).z() < 0) std::reverse(p.begin(), p.end());
    out.geom = arena.addPolygon(p);
  } else {
    out.geom = arena.addPolyhedron(faces);
  }
}

Mat3 keepPolygonFrame(const Mat3& axes, const WorldGeometry& g) {
  return g.kind == GeomKind::Polygon ? polygonFrame(axes, faceNormal(g.faces[0])) : axes;
}

}  // namespace

std::vector<Polygon3> fitScopeAroundWorldFaces(const Scope& base, const Mat3& axes,
                                               const std::vector<Polygon3>& worldFaces, Scope& out) {
  const Mat3 inverse = axes.transpose();  // orthonormal (mirrored too)
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Polygon3& f : worldFaces)
    for (const Vec3& p : f) {
      const Vec3 l = inverse * p;
      lo = lo.cwiseMin(l), hi = hi.cwiseMax(l);
    }
  out = base;
  out.axes = axes;
  out.P = axes * lo;
  out.S = hi - lo;
  const double extent = out.S.maxCoeff();
  for (int k = 0; k < 3; ++k)
    if (out.S[k] <= 1e-9 * extent) out.S[k] = 0.0;
  const bool mirrored = axes.determinant() < 0;
  std::vector<Polygon3> faces;
  faces.reserve(worldFaces.size());
  for (const Polygon3& f : worldFaces) {
    Polygon3 u;
    for (const Vec3& p : f) {
      const Vec3 l = inverse * p - lo;
      Vec3 n;
      for (int k = 0; k < 3; ++k) n[k] = out.S[k] > 0 ? l[k] / out.S[k] : 0.0;
      u.push_back(n);
    }
    if (mirrored) std::reverse(u.begin(), u.end());  // counter-clockwise in the mirrored frame
    faces.push_back(std::move(u));
  }
  return faces;
}

bool lyingOnGround(const GeomRef& geom, const GeometryArena& arena) {
  if (geom.kind != GeomKind::Polyhedron || geom.count != 1) return false;
  const GeometryArena::Face& f = arena.face(geom, 0);
  for (uint32_t i = 0; i < f.count; ++i)
    if (arena.facePoints(f)[i].y() != 0.0) return false;
  return f.count >= 3;
}

void asGroundFace(Part& part, const Vec3& xAxis, GeometryArena& arena) {
  WorldGeometry g;
  std::string error;
  if (part.geom.kind != GeomKind::Polygon || !worldGeometry(part.scope, part.geom, arena, "", g, error)) return;
  const Vec3 up = part.scope.Z();
  Vec3 x = xAxis - xAxis.dot(up) * up;
  if (!(x.norm() > 1e-12)) x = part.scope.X();
  x.normalize();
  Mat3 axes;
  axes.col(0) = x;
  axes.col(1) = up;
  axes.col(2) = x.cross(up);
  g.kind = GeomKind::Polyhedron;  // one face, counter-clockwise seen from above
  fit(part.scope, axes, g, arena, part);
}

bool rotateScope(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const Vec3& degrees, Part& out,
                 std::string& error) {
  WorldGeometry g;
  if (!worldGeometry(scope, geom, arena, "rotateScope", g, error)) return false;
  Scope turned = scope;
  for (int k = 0; k < 3; ++k) rotateLocal(turned, k, degrees[k]);
  fit(scope, keepPolygonFrame(turned.axes, g), g, arena, out);
  return true;
}

bool alignScopeToAxes(const Scope& scope, const GeomRef& geom, GeometryArena& arena, int axis, Part& out,
                      std::string& error) {
  WorldGeometry g;
  if (!worldGeometry(scope, geom, arena, "alignScopeToAxes", g, error)) return false;
  Mat3 axes = Mat3::Identity();
  if (axis >= 0 && axis < 3) {
    // op_alignScopeToAxes: that axis becomes the world's; the second is the scope's z (for
    // x) or x (for y and z) projected onto the plane across it; the third completes the frame.
    const Vec3 along = Vec3::Unit(axis);
    const int second = axis == 0 ? 2 : 0, third = 3 - axis - second;
    const Vec3 projected = scope.axes.col(second) - scope.axes.col(second).dot(along) * along;
    if (projected.norm() > 1e-9) {
      axes.col(axis) = along;
      axes.col(second) = projected.normalized();
      axes.col(third) = axes.col((third + 1) % 3).cross(axes.col((third + 2) % 3));
    } else {  // that axis lies along the world's: the least turn
      axes = rotationOnto(scope.axes.col(axis), along) * scope.axes;
    }
  }
  fit(scope, keepPolygonFrame(axes, g), g, arena, out);
  return true;
}

bool alignScopeToGeometry(const Scope& scope, const GeomRef& geom, GeometryArena& arena, int upAxis, int face,
                          int edge, Part& out, std::string& error) {
  WorldGeometry g;
  if (!worldGeometry(scope, geom, arena, "alignScopeToGeometry", g, error)) return false;
  const int faces = static_cast<int>(g.faces.size());
  if (face < 0 && face != -1) face += faces;  // CityEngine's negative indices count from the end
  int f = face;
  if (face == -1) {
    f = 0;
    for (int k = 1; k < faces; ++k)
      if (faceNormal(g.faces[k]).norm() > faceNormal(g.faces[f]).norm()) f = k;
  }
  if (f < 0 || f >= faces) {
    error = "alignScopeToGeometry: no face " + std::to_string(face) + " (the geometry has " + std::to_string(faces) +
            ")";
    return false;
  }
  const Polygon3& poly = g.faces[f];
  const int corners = static_cast<int>(poly.size());
  int e = edge;
  if (edge < -1) e = edge + corners;
  if (edge == -1) {
    e = 0;
    for (int k = 1; k < corners; ++k)
      if ((poly[(k + 1) % corners] - poly[k]).norm() > (poly[(e + 1) % corners] - poly[e]).norm()) e = k;
  }
  if (e < 0 || e >= corners) {
    error = "alignScopeToGeometry: face " + std::to_string(f) + " has no edge " + std::to_string(edge) + " (it has " +
            std::to_string(corners) + ")";
    return false;
  }
  const Vec3 up = faceNormal(poly).normalized();
  Vec3 x = poly[(e + 1) % corners] - poly[e];
  x -= up * up.dot(x);
  if (!(x.norm() > 0) || !up.allFinite()) {
    error = "alignScopeToGeometry: face " + std::to_string(f) + " or its edge " + std::to_string(e) + " has no extent";
    return false;
  }
  x.normalize();
  Mat3 axes;
  axes.col(0) = x;
  if (upAxis == 1) {
    axes.col(1) = up;
    axes.col(2) = x.cross(up);
  } else {
    axes.col(2) = up;
    axes.col(1) = up.cross(x);
  }
  fit(scope, keepPolygonFrame(axes, g), g, arena, out);
  return true;
}

bool mirrorScope(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const bool flip[3], Part& out,
                 std::string& error) {
  WorldGeometry g;
  if (!worldGeometry(scope, geom, arena, "mirrorScope", g, error)) return false;
  Mat3 axes = scope.axes;
  for (int k = 0; k < 3; ++k)
    if (flip[k]) axes.col(k) = -axes.col(k);
  fit(scope, axes, g, arena, out);  // the origin: the box's corner on the far side of each flipped axis
  return true;
}

bool mirrorGeometry(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const bool flip[3], Part& out,
                    std::string& error) {
  out = Part{scope, geom, false, 0};
  if (geom.kind == GeomKind::Box || geom.kind == GeomKind::Edge) return true;  // symmetric in its scope
  LocalGeometry local = loadGeometry(arena, geom);
  const bool odd = (flip[0] != flip[1]) != flip[2];
  for (Polygon3& f : local.faces) {
    for (Vec3& u : f)
      for (int k = 0; k < 3; ++k)
        if (flip[k] && scope.S[k] > 0) u[k] = 1.0 - u[k];
    if (odd) std::reverse(f.begin(), f.end());  // a mirror image turns faces inside out
  }
  if (geom.kind == GeomKind::Polygon && newellNormal(local.faces[0]).z() < 0)
    std::reverse(local.faces[0].begin(), local.faces[0].end());
  out.geom = storeGeometry(arena, local);
  (void)error;
  return true;
}

bool reverseNormals(const Scope& scope, const GeomRef& geom, GeometryArena& arena, Part& out, std::string& error) {
  WorldGeometry g;
  if (!worldGeometry(scope, geom, arena, "reverseNormals", g, error)) return false;
  for (Polygon3& f : g.faces) std::reverse(f.begin(), f.end());
  if (g.kind == GeomKind::Polygon) {
    // fgsg's polygon frame has Z along the normal: the frame turns over (half a turn about X).
    Mat3 axes = scope.axes;
    if (geom.kind == GeomKind::Box) axes = polygonFrame(axes, faceNormal(g.faces[0]));
    axes.col(1) = -axes.col(1), axes.col(2) = -axes.col(2);
    fit(scope, axes, g, arena, out);
    return true;
  }
  g.box = false;
  fit(scope, scope.axes, g, arena, out);
  return true;
}

bool deleteHoles(const Scope& scope, const GeomRef& geom, GeometryArena& arena, Part& out, std::string& error) {
  out = Part{scope, geom, false, 0};
  // Boxes have no holes. A polygon's or a solid's face (the `.cga` dialect's lots are
  // one-face solids) keeps its outline; the outline holds every corner, so the scope stays.
  if (geom.kind != GeomKind::Polygon && geom.kind != GeomKind::Polyhedron) return true;
  LocalGeometry local = loadGeometry(arena, geom);
  bool changed = false;
  for (Polygon3& f : local.faces) {
    std::vector<Polygon3> rings = ringsOf(f);
    if (rings.size() > 1) f = std::move(rings[0]), changed = true;
  }
  if (changed) out.geom = storeGeometry(arena, local);
  (void)error;
  return true;
}

namespace {

// cleanupGeometry's steps on world faces (a face soup; corners match by position).

// Every corner moved onto the first corner met within `eps` of it (corners on a grid of
// cells `eps` wide; a corner looks in its cell and the 26 around it).
bool mergeCorners(std::vector<Polygon3>& faces, double eps) {
  std::map<std::array<long long, 3>, std::vector<Vec3>> cells;
  const double cell = std::max(eps, 1e-9);
  bool moved = false;
  for (Polygon3& f : faces)
    for (Vec3& p : f) {
      std::array<long long, 3> c;
      for (int k = 0; k < 3; ++k) c[k] = static_cast<long long>(std::floor(p[k] / cell));
      const Vec3* found = nullptr;
      for (int dx = -1; dx <= 1 && !found; ++dx)
        for (int dy = -1; dy <= 1 && !found; ++dy)
          for (int dz = -1; dz <= 1 && !found; ++dz) {
            const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
            if (it == cells.end()) continue;
            for (const Vec3& q : it->second)
              if ((q - p).norm() <= eps) {
                found = &q;
                break;
              }
          }
      if (found) {
        moved |= *found != p;
        p = *found;
      } else {
        cells[c].push_back(p);
      }
    }
  // A corner equal to the one before it is the same corner.
  for (Polygon3& f : faces) {
    Polygon3 kept;
    for (const Vec3& p : f)
      if (kept.empty() || p != kept.back()) kept.push_back(p);
    while (kept.size() > 1 && kept.front() == kept.back()) kept.pop_back();
    moved |= kept.size() != f.size();
    f = std::move(kept);
  }
  return moved;
}

// Corners where the outline goes on straight (turns by `maxTurn` radians or less) dropped.
bool dropStraightCorners(std::vector<Polygon3>& faces, double maxTurn) {
  bool changed = false;
  for (Polygon3& f : faces)
    for (bool again = true; again && f.size() > 3;) {
      again = false;
      for (size_t i = 0; i < f.size() && f.size() > 3; ++i) {
        const Vec3 in = f[i] - f[(i + f.size() - 1) % f.size()], out = f[(i + 1) % f.size()] - f[i];
        if (!(in.norm() > 0 && out.norm() > 0) || in.dot(out) <= 0) continue;
        if (std::atan2(in.cross(out).norm(), in.dot(out)) <= maxTurn) {
          f.erase(f.begin() + static_cast<long>(i));
          again = changed = true;
          break;
        }
      }
    }
  return changed;
}

// Faces of `maxArea` m2 or less, and second copies of a face (the same corners), dropped.
bool dropDegenerateFaces(std::vector<Polygon3>& faces, double maxArea) {
  std::set<std::vector<std::array<double, 3>>> seen;
  std::vector<Polygon3> kept;
  for (Polygon3& f : faces) {
    if (f.size() < 3 || newellNormal(f).norm() / 2 <= maxArea) continue;
    std::vector<std::array<double, 3>> key;
    for (const Vec3& p : f) key.push_back({p.x(), p.y(), p.z()});
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) continue;
    kept.push_back(std::move(f));
  }
  const bool changed = kept.size() != faces.size();
  faces = std::move(kept);
  return changed;
}

// A ring's back-and-forth spikes (a, b, a) folded away: what joining two faces along more
// than one shared edge leaves.
void foldSpikes(Polygon3& f) {
  for (bool again = true; again && f.size() >= 3;) {
    again = false;
    for (size_t i = 0; i < f.size() && f.size() >= 3; ++i) {
      const size_t prev = (i + f.size() - 1) % f.size(), next = (i + 1) % f.size();
      if (f[prev] == f[next]) {
        // drop b and one of the a's
        const size_t hi = std::max(i, next), lo = std::min(i, next);
        f.erase(f.begin() + static_cast<long>(hi));
        f.erase(f.begin() + static_cast<long>(lo));
        again = true;
        break;
      }
    }
  }
}

// Faces that share an edge (one walks it a -> b, the other b -> a) and whose normals differ by
// `maxAngle` radians or less become one face, the shared edge removed.
bool mergeCoplanarFaces(std::vector<Polygon3>& faces, double maxAngle) {
  bool changed = false;
  for (bool again = true; again;) {
    again = false;
    std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, std::pair<size_t, size_t>> edges;
    auto key = [](const Vec3& a, const Vec3& b) {
      return std::make_pair(std::array<double, 3>{a.x(), a.y(), a.z()}, std::array<double, 3>{b.x(), b.y(), b.z()});
    };
    for (size_t fi = 0; fi < faces.size() && !again; ++fi) {
      const Polygon3& f = faces[fi];
      for (size_t i = 0; i < f.size() && !again; ++i) {
        const Vec3& a = f[i];
        const Vec3& b = f[(i + 1) % f.size()];
        const auto other = edges.find(key(b, a));
        if (other != edges.end() && other->second.first != fi) {
          const size_t gi = other->second.first, j = other->second.second;
          const Vec3 n = newellNormal(f), m = newellNormal(faces[gi]);
          if (n.norm() > 0 && m.norm() > 0 && std::atan2(n.cross(m).norm(), n.dot(m)) <= maxAngle) {
            // f runs ... a b ...; g runs ... b a ...: f up to a, then g from after a round to b, then f from b on.
            const Polygon3& g = faces[gi];
            Polygon3 joined;
            for (size_t k = 0; k <= i; ++k) joined.push_back(f[k]);
            for (size_t k = 2; k < g.size(); ++k) joined.push_back(g[(j + k) % g.size()]);
            for (size_t k = i + 1; k < f.size(); ++k) joined.push_back(f[k]);
            foldSpikes(joined);
            faces[std::min(fi, gi)] = std::move(joined);
            faces.erase(faces.begin() + static_cast<long>(std::max(fi, gi)));
            again = changed = true;
            break;
          }
        }
        edges.emplace(key(a, b), std::make_pair(fi, i));
      }
    }
  }
  return changed;
}

}  // namespace

bool cleanupGeometry(const Scope& scope, const GeomRef& geom, GeometryArena& arena, int what, double tolerance,
                     Part& out, std::string& error) {
  WorldGeometry g;
  if (!worldGeometry(scope, geom, arena, "cleanupGeometry", g, error)) return false;
  if (!(tolerance >= 0 && tolerance <= 1)) {
    error = "cleanupGeometry: the tolerance must be a number from 0 to 1";
    return false;
  }
  // op_cleanupGeometry's scale: 1 takes corners up to 1 m apart as one, edges and normals up
  // to 10 degrees apart as straight and coplanar, faces up to 1 m2 as without area; 0 only
  // exact matches (here: within 1e-9), values between in proportion.
  constexpr double kExact = 1e-9;
  const double distance = std::max(tolerance, kExact);
  const double angle = std::max(tolerance * 10.0 * std::numbers::pi / 180.0, kExact);
  const double area = std::max(tolerance, kExact * kExact);
  bool changed = false;
  if (what & 1) changed |= mergeCorners(g.faces, distance);
  if (what & 8) changed |= mergeCoplanarFaces(g.faces, angle);
  if (what & 2) changed |= dropStraightCorners(g.faces, angle);
  if (what & 4) changed |= dropDegenerateFaces(g.faces, area);
  if (!changed) {
    out = Part{scope, geom, false, 0};
    return true;
  }
  g.faces.erase(std::remove_if(g.faces.begin(), g.faces.end(), [](const Polygon3& f) { return f.size() < 3; }),
                g.faces.end());
  if (g.faces.empty()) {
    error = "cleanupGeometry: no face is left";
    return false;
  }
  g.box = false;
  fit(scope, scope.axes, g, arena, out);
  return true;
}

}  // namespace fgsg::rt::cga
