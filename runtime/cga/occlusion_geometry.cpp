// inside / overlaps / touches between a shape's triangles and a closed occluder, and the
// distance between two scope boxes (occlusion_geometry.h).
//
// How a query is decided. Points are classified against a closed soup as on its surface
// (within the tolerance), inside (winding number 1) or outside. The witnesses looked at:
// every corner, edge midpoint and triangle centre of the query's surface; where an edge
// of one surface pierces a triangle of the other, points a step (10 tolerances) to either
// side of the crossing on the query's surface; and, for a closed query, its triangle
// centres stepped inward, and the same witnesses of the occluder's surface against the
// query. Overlaps: a witness lies inside the other solid. Inside: no witness of the query
// lies outside the occluder. Touches: overlaps, or two triangles come within the
// tolerance. The inward steps and the crossings find what corners alone miss: two equal
// boxes, boxes sharing a face plane (a split's pieces), two bars crossing like a plus.
#include "runtime/cga/occlusion_geometry.h"

#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::cga {
namespace {

using Triangle = std::array<Vec3, 3>;

enum class Side { In, On, Out };

Vec3 closestOnTriangle(const Vec3& p, const Triangle& t) {
  // Ericson, Real-Time Collision Detection, 5.1.5: the Voronoi regions of the triangle.
  const Vec3 &a = t[0], &b = t[1], &c = t[2];
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double sum = va + vb + vc;
  if (!(sum > 0)) return a;  // a degenerate triangle: its first corner
  return a + ab * (vb / sum) + ac * (vc / sum);
}

// Where segment pq passes through the triangle, its ends strictly on opposite sides of
// the triangle's plane (a segment in the plane is the edge distances' case).
bool pierces(const Vec3& p, const Vec3& q, const Triangle& t, Vec3& hit) {
  const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]);
  const double dp = n.dot(p - t[0]), dq = n.dot(q - t[0]);
  if ((dp >= 0 && dq >= 0) || (dp <= 0 && dq <= 0)) return false;
  const Vec3 x = p + dp / (dp - dq) * (q - p);
  for (int k = 0; k < 3; ++k)
    if (n.dot((t[(k + 1) % 3] - t[k]).cross(x - t[k])) < 0) return false;
  hit = x;
  return true;
}

bool boxesMeet(const Vec3& lo1, const Vec3& hi1, const Vec3& lo2, const Vec3& hi2, double margin) {
  return !((hi1.array() + margin < lo2.array()).any() || (hi2.array() + margin < lo1.array()).any());
}

void bounds(const Triangle& t, Vec3& lo, Vec3& hi) {
  lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]);
  hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
}

Side classify(const Vec3& p, const TriangleSoup& solid, double tol) {
  if ((p.array() < solid.lo.array() - tol).any() || (p.array() > solid.hi.array() + tol).any()) return Side::Out;
  double best = INFINITY;
  for (const Triangle& t : solid.triangles) best = std::min(best, (closestOnTriangle(p, t) - p).norm());
  if (best <= tol) return Side::On;
  return std::abs(windingNumber(p, solid)) > 0.5 ? Side::In : Side::Out;
}

// The query's witnesses on its own surface: corners, edge midpoints, centres.
std::vector<Vec3> surfaceWitnesses(const TriangleSoup& s) {
  std::vector<Vec3> out;
  out.reserve(s.triangles.size() * 7);
  for (const Triangle& t : s.triangles) {
    for (int k = 0; k < 3; ++k) out.push_back(t[k]), out.push_back(0.5 * (t[k] + t[(k + 1) % 3]));
    out.push_back((t[0] + t[1] + t[2]) / 3.0);
  }
  return out;
}

// Points of `on`'s surface a step to either side of where the two surfaces cross: along
// `on`'s edge where it pierces the other, and across the other's edge where that pierces `on`.
std::vector<Vec3> crossingWitnesses(const TriangleSoup& on, const TriangleSoup& other, double step, double tol) {
  std::vector<Vec3> out;
  for (const Triangle& t : on.triangles) {
    Vec3 tlo, thi;
    bounds(t, tlo, thi);
    if (!boxesMeet(tlo, thi, other.lo, other.hi, tol)) continue;
    const Vec3 tn = (t[1] - t[0]).cross(t[2] - t[0]);
    if (!(tn.squaredNorm() > 0)) continue;
    for (const Triangle& u : other.triangles) {
      Vec3 ulo, uhi;
      bounds(u, ulo, uhi);
      if (!boxesMeet(tlo, thi, ulo, uhi, tol)) continue;
      Vec3 x;
      for (int k = 0; k < 3; ++k) {
        const Vec3 &p = t[k], &q = t[(k + 1) % 3];
        if (!pierces(p, q, u, x)) continue;
        const Vec3 dir = (q - p).normalized();
        const double len = (q - p).norm(), at = (x - p).norm();
        out.push_back(x - std::min(step, 0.5 * at) * dir);
        out.push_back(x + std::min(step, 0.5 * (len - at)) * dir);
      }
      const Vec3 un = (u[1] - u[0]).cross(u[2] - u[0]);
      Vec3 across = un - un.dot(tn) / tn.squaredNorm() * tn;  // u's normal within t's plane
      if (!(across.norm() > 1e-12 * un.norm())) continue;
      across.normalize();
      for (int k = 0; k < 3; ++k) {
        if (!pierces(u[k], u[(k + 1) % 3], t, x)) continue;
        for (double sign : {-1.0, 1.0}) {
          const Vec3 w = x + sign * step * across;
          if ((closestOnTriangle(w, t) - w).norm() <= 1e-9 * (1.0 + step)) out.push_back(w);
        }
      }
    }
  }
  return out;
}

// A closed soup's triangle centres a step inside it.
std::vector<Vec3> inwardWitnesses(const TriangleSoup& s, double step) {
  std::vector<Vec3> out;
  for (const Triangle& t : s.triangles) {
    const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]);
    if (n.squaredNorm() > 0) out.push_back((t[0] + t[1] + t[2]) / 3.0 - step * n.normalized());
  }
  return out;
}

bool anyInside(const std::vector<Vec3>& points, const TriangleSoup& solid, double tol) {
  for (const Vec3& p : points)
    if (classify(p, solid, tol) == Side::In) return true;
  return false;
}

bool overlaps(const TriangleSoup& q, const TriangleSoup& o, double tol) {
  const double step = 10 * tol;
  if (anyInside(surfaceWitnesses(q), o, tol) || anyInside(crossingWitnesses(q, o, step, tol), o, tol)) return true;
  if (!q.closed) return false;
  for (const Vec3& p : inwardWitnesses(q, step))
    if (classify(p, q, tol) == Side::In && classify(p, o, tol) == Side::In) return true;
  return anyInside(surfaceWitnesses(o), q, tol) || anyInside(crossingWitnesses(o, q, step, tol), q, tol);
}

bool inside(const TriangleSoup& q, const TriangleSoup& o, double tol) {
  if (q.triangles.empty()) return false;
  if (!boxesMeet(q.lo, q.hi, o.lo, o.hi, tol)) return false;
  for (const Vec3& p : surfaceWitnesses(q))
    if (classify(p, o, tol) == Side::Out) return false;
  for (const Vec3& p : crossingWitnesses(q, o, 10 * tol, tol))
    if (classify(p, o, tol) == Side::Out) return false;
  return true;
}

double soupDistance(const TriangleSoup& a, const TriangleSoup& b, double stopBelow) {
  double best = INFINITY;
  for (const Triangle& t : a.triangles) {
    Vec3 tlo, thi;
    bounds(t, tlo, thi);
    for (const Triangle& u : b.triangles) {
      Vec3 ulo, uhi;
      bounds(u, ulo, uhi);
      // Boxes farther apart than the best so far cannot hold a closer pair.
      if (std::isfinite(best) && !boxesMeet(tlo, thi, ulo, uhi, best)) continue;
      best = std::min(best, triangleDistance(t, u));
      if (best <= stopBelow) return best;
    }
  }
  return best;
}

TriangleSoup boxSoup(const Scope& s) {
  const double tol = 1e-12 * (1.0 + s.S.cwiseAbs().maxCoeff());
  std::array<Vec3, 8> c;
  for (int k = 0; k < 8; ++k)
    c[k] = s.toWorld(Vec3(k & 1 ? s.S.x() : 0.0, k & 2 ? s.S.y() : 0.0, k & 4 ? s.S.z() : 0.0));
  // The faces of the cube by corner bits (x 1, y 2, z 4), each as two triangles.
  static const int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Triangle> tris;
  int flats = 0;
  for (int a = 0; a < 3; ++a) flats += std::abs(s.S[a]) <= tol;
  for (const auto& f : kFaces) {
    tris.push_back({c[f[0]], c[f[1]], c[f[2]]});
    tris.push_back({c[f[0]], c[f[2]], c[f[3]]});
  }
  TriangleSoup soup = fromTriangles(std::move(tris));
  if (flats > 0) soup.closed = false;
  return soup;
}

}  // namespace

double pointTriangleDistance(const Vec3& p, const std::array<Vec3, 3>& t) { return (closestOnTriangle(p, t) - p).norm(); }

double segmentDistance(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  // Ericson 5.1.9: the closest points of two segments.
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0, t = 0;
  if (a <= 0 && e <= 0) return r.norm();
  if (a <= 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
      else if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  return ((p1 + s * d1) - (p2 + t * d2)).norm();
}

double triangleDistance(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  // Triangles that meet have an edge of one through the other; else the closest points
  // are a corner and a triangle or two edges.
  Vec3 x;
  for (int k = 0; k < 3; ++k)
    if (pierces(a[k], a[(k + 1) % 3], b, x) || pierces(b[k], b[(k + 1) % 3], a, x)) return 0;
  double best = INFINITY;
  for (int k = 0; k < 3; ++k) {
    best = std::min({best, pointTriangleDistance(a[k], b), pointTriangleDistance(b[k], a)});
    for (int j = 0; j < 3; ++j) best = std::min(best, segmentDistance(a[k], a[(k + 1) % 3], b[j], b[(j + 1) % 3]));
  }
  return best;
}

double windingNumber(const Vec3& p, const TriangleSoup& soup) {
  // Van Oosterom and Strackee's solid angle of each triangle seen from p.
  double sum = 0;
  for (const Triangle& t : soup.triangles) {
    const Vec3 a = t[0] - p, b = t[1] - p, c = t[2] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    sum += 2 * std::atan2(num, den);
  }
  return sum / (4 * M_PI);
}

TriangleSoup fromTriangles(std::vector<std::array<Vec3, 3>> triangles) {
  TriangleSoup s;
  s.triangles = std::move(triangles);
  if (s.triangles.empty()) return s;
  s.lo = s.hi = s.triangles[0][0];
  Vec3 vectorArea = Vec3::Zero();
  double area = 0, volume = 0;
  for (const Triangle& t : s.triangles) {
    for (const Vec3& p : t) s.lo = s.lo.cwiseMin(p), s.hi = s.hi.cwiseMax(p);
    const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]);
    vectorArea += n;
    area += n.norm();
    volume += t[0].dot(t[1].cross(t[2]));
  }
  const double size = (s.hi - s.lo).norm();
  // Closed: the vector areas cancel and something is enclosed.
  s.closed = area > 0 && vectorArea.norm() <= 1e-9 * area && std::abs(volume) > 1e-9 * area * size;
  if (s.closed && volume < 0)
    for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
  return s;
}

TriangleSoup shapeTriangles(const Scope& scope, const GeomRef& geom, const GeometryArena& arena) {
  if (geom.kind == GeomKind::Edge) return {};
  // A whole box is its scope box (a flat one its rectangle, seen from both sides).
  if (geom.kind == GeomKind::Box) return boxSoup(scope);
  // Each face ear-clipped in world space, in doubles (triangulate() writes floats, too
  // coarse for a tenth of a millimetre a kilometre from the origin).
  auto toWorld = [&](const Vec3& n) { return scope.toWorld(scope.S.cwiseProduct(n)); };
  std::vector<Triangle> tris;
  Polygon3 world;
  std::vector<uint32_t> corners;
  for (const Polygon3& f : loadGeometry(arena, geom).faces) {
    world.clear();
    for (const Vec3& p : f) world.push_back(toWorld(p));
    corners.clear();
    earClip(world, corners);
    for (size_t k = 0; k + 2 < corners.size(); k += 3)
      tris.push_back({world[corners[k]], world[corners[k + 1]], world[corners[k + 2]]});
  }
  return fromTriangles(std::move(tris));
}

bool contact(Contact test, const TriangleSoup& query, const TriangleSoup& occluder, double tolerance) {
  if (!occluder.closed || query.triangles.empty()) return false;
  if (!boxesMeet(query.lo, query.hi, occluder.lo, occluder.hi, tolerance)) return false;
  switch (test) {
    case Contact::Inside: return inside(query, occluder, tolerance);
    case Contact::Overlaps: return overlaps(query, occluder, tolerance);
    case Contact::Touches:
      return overlaps(query, occluder, tolerance) || soupDistance(query, occluder, tolerance) <= tolerance;
  }
  return false;
}

double scopeDistance(const Scope& a, const Scope& b) {
  const TriangleSoup sa = boxSoup(a), sb = boxSoup(b);
  for (const auto& [from, to] : {std::pair{&sa, &sb}, std::pair{&sb, &sa}})
    if (to->closed)
      for (const Triangle& t : from->triangles)
        if (classify(t[0], *to, 0) != Side::Out) return 0;
  return soupDistance(sa, sb, 0);
}

}  // namespace fgsg::rt::cga
