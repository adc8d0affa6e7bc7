// Setback (CityEngine's setback, shapeL/U/O) and innerRectangle on a polygon seen in its
// own plane. A set-back edge moves inward along its normal; where two moved edges (or a
// moved edge and a kept one) meet is the remainder's corner, so each edge's band runs
// between the two corners' bisecting lines, as the straight skeleton's offset does while
// no edge vanishes.
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"
#include "runtime/cga/street_edges.h"
#include "runtime/planar.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Corners that repeat the one before (a band ending in a point) taken out.
std::vector<Vec2> distinct(const std::vector<Vec2>& ring, double eps) {
  std::vector<Vec2> out;
  for (const Vec2& p : ring)
    if (out.empty() || (p - out.back()).norm() > eps) out.push_back(p);
  while (out.size() > 1 && (out.front() - out.back()).norm() <= eps) out.pop_back();
  return out;
}

// A ring in metres of the polygon's plane (counter-clockwise; holes clockwise) as a part
// with the polygon's axes, its scope fitted to it.
bool planePart(const FlatPolygon& poly, const std::vector<Vec2>& outline, const std::vector<std::vector<Vec2>>& holes,
               GeometryArena& arena, Part& out, std::string& error) {
  std::vector<Vec2> ring = outline;
  if (!holes.empty() && !joinHolesInPlane(outline, holes, "Setback: ", ring, error)) return false;
  Vec2 lo = ring[0], hi = ring[0];
  for (const Vec2& p : ring) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec2 size = hi - lo;
  Polygon3 normalised;
  for (const Vec2& p : ring)
    normalised.emplace_back(size.x() > 0 ? (p.x() - lo.x()) / size.x() : 0.0,
                            size.y() > 0 ? (p.y() - lo.y()) / size.y() : 0.0, 0.0);
  if (newellNormal(normalised).z() < 0) std::reverse(normalised.begin(), normalised.end());
  out = Part{};
  out.scope = poly.scope;
  out.scope.P = poly.scope.toWorld(Vec3(lo.x(), lo.y(), 0.0));
  out.scope.S = Vec3(size.x(), size.y(), 0.0);
  out.geom = arena.addPolygon(normalised);
  if (poly.groundFace) asGroundFace(out, poly.xAxis, arena);
  return true;
}

}  // namespace

bool flatPolygon(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const char* what, FlatPolygon& out,
                 std::string& error, bool takeHoles) {
  Scope planar = scope;
  GeomRef polygon = geom;
  out.groundFace = lyingOnGround(geom, arena);
  out.xAxis = scope.X();
  if (out.groundFace) {
    // fgsg's polygon frame of the ground face: x kept, z up (its y), y = z x x.
    const GeometryArena::Face& f = arena.face(geom, 0);
    Polygon3 poly;
    for (uint32_t i = 0; i < f.count; ++i) poly.emplace_back(arena.facePoints(f)[i].x(), 1.0 - arena.facePoints(f)[i].z(), 0.0);
    if (newellNormal(poly).z() < 0) std::reverse(poly.begin(), poly.end());
    planar.axes.col(1) = -scope.Z();
    planar.axes.col(2) = scope.Y();
    planar.P = scope.P + scope.Z() * scope.S.z();
    planar.S = Vec3(scope.S.x(), scope.S.z(), 0.0);
    polygon = arena.addPolygon(poly);
  } else if (geom.kind == GeomKind::Box && scope.S.y() == 0.0 && scope.S.x() > 0.0 && scope.S.z() > 0.0) {
    Part part;  // a footprint S(w, 0, d): its rectangle as Footprint makes it
    if (!footprint(scope, {{0, 0}, {scope.S.x(), 0}, {scope.S.x(), scope.S.z()}, {0, scope.S.z()}}, {}, arena, part,
                   error))
      return false;
    planar = part.scope;
    polygon = part.geom;
  } else if (geom.kind != GeomKind::Polygon || !(scope.S.x() > 0.0 && scope.S.y() > 0.0)) {
    error = std::string(what) + ": expects a polygon (a lot, a Footprint, a Comp face) or a flat footprint S(w, 0, d)";
    return false;
  }
  const Polygon3 pts(arena.polygon(polygon), arena.polygon(polygon) + polygon.count);
  const std::vector<Polygon3> rings = ringsOf(pts);
  if (rings.size() > 1 && !takeHoles) {
    error = std::string(what) + ": the polygon has holes (a courtyard), which it does not take: deleteHoles first";
    return false;
  }
  out.scope = planar;
  out.ring.clear();
  out.holes.clear();
  for (size_t r = 0; r < rings.size(); ++r) {
    std::vector<Vec2> ring;
    for (const Vec3& u : rings[r]) ring.emplace_back(u.x() * planar.S.x(), u.y() * planar.S.y());
    ring = distinct(ring, 1e-12 * planar.S.maxCoeff());
    if ((twiceRingArea(ring) < 0) == (r == 0)) std::reverse(ring.begin(), ring.end());
    if (r == 0) out.ring = std::move(ring);
    else out.holes.push_back(std::move(ring));
  }
  return true;
}

std::vector<unsigned> edgeSelectors(const FlatPolygon& polygon, const StreetEdges* streets) {
  const size_t n = polygon.ring.size();
  std::vector<unsigned> out(n, 0);
  for (size_t i = 0; i < n; ++i) {
    const Vec2 d = polygon.ring[(i + 1) % n] - polygon.ring[i];
    const Vec2 m(d.y(), -d.x());  // outward: the polygon runs counter-clockwise
    unsigned c = std::abs(m.y()) >= std::abs(m.x()) ? (m.y() < 0 ? kEdgeFront : kEdgeBack)
                                                     : (m.x() > 0 ? kEdgeRight : kEdgeLeft);
    const Vec3 w = polygon.scope.X() * m.x() + polygon.scope.Y() * m.y();
    c |= std::abs(w.z()) >= std::abs(w.x()) ? (w.z() < 0 ? kEdgeNorth : kEdgeSouth) : (w.x() > 0 ? kEdgeEast : kEdgeWest);
    out[i] = c;
  }
  if (streets) {
    // The lot's street widths: each edge's ends and outward direction in the world.
    const Scope& s = polygon.scope;
    for (size_t i = 0; i < n; ++i) {
      const Vec2 p = polygon.ring[i], q = polygon.ring[(i + 1) % n];
      const Vec3 a = s.P + s.X() * p.x() + s.Y() * p.y(), b = s.P + s.X() * q.x() + s.Y() * q.y();
      const Vec3 outward = s.X() * (q - p).y() - s.Y() * (q - p).x();
      const unsigned side = streetSide(*streets, outward, &a, &b);
      out[i] |= (side & kStreetFront ? kEdgeStreetFront : 0u) | (side & kStreetBack ? kEdgeStreetBack : 0u) |
                (side & kStreetLeft ? kEdgeStreetLeft : 0u) | (side & kStreetRight ? kEdgeStreetRight : 0u);
    }
    return out;
  }
  for (size_t i = 0; i < n; ++i)  // street.back / left / right: the scope's
    out[i] |= (out[i] & kEdgeBack ? kEdgeStreetBack : 0u) | (out[i] & kEdgeLeft ? kEdgeStreetLeft : 0u) |
              (out[i] & kEdgeRight ? kEdgeStreetRight : 0u);
  // No street information: the street is in front, along the edge facing the front most
  // squarely (a CityEngine lot's first edge, which its x runs along); the longer on a tie.
  size_t street = n;
  double best = -2, bestLength = 0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 d = polygon.ring[(i + 1) % n] - polygon.ring[i];
    if (!(out[i] & kEdgeFront) || !(d.norm() > 0)) continue;
    const double facing = d.x() / d.norm();  // the outward normal (d.y, -d.x) against -Y
    if (facing > best + 1e-12 || (facing > best - 1e-12 && d.norm() > bestLength)) best = facing, bestLength = d.norm(), street = i;
  }
  if (street < n) out[street] |= kEdgeStreetFront;
  return out;
}

unsigned edgeSelectorMask(const std::string& label) {
  std::string l = label;
  if (!l.empty() && l.back() == '=') l.pop_back();
  if (l == "front") return kEdgeFront;
  if (l == "back") return kEdgeBack;
  if (l == "left") return kEdgeLeft;
  if (l == "right") return kEdgeRight;
  if (l == "side") return kEdgeLeft | kEdgeRight;
  if (l == "streetFront") return kEdgeStreetFront;
  if (l == "streetBack") return kEdgeStreetBack;
  if (l == "streetLeft") return kEdgeStreetLeft;
  if (l == "streetRight") return kEdgeStreetRight;
  if (l == "streetSide") return kEdgeStreetLeft | kEdgeStreetRight;
  if (l == "north") return kEdgeNorth;
  if (l == "south") return kEdgeSouth;
  if (l == "east") return kEdgeEast;
  if (l == "west") return kEdgeWest;
  if (l == "all") return ~0u;
  return 0;
}

// The remainder's corners: each edge's line moved inward by its distance, corner i where
// lines i - 1 and i meet. False when an edge would vanish or the remainder cross itself.
static bool insetCorners(const std::vector<Vec2>& p, const std::vector<double>& distance, double eps,
                         std::vector<Vec2>& q, std::string& error) {
  const size_t n = p.size();
  // Each edge's line moved inward; the remainder's corner i where lines i - 1 and i meet.
  std::vector<Vec2> t(n), a(n);
  q.assign(n, Vec2::Zero());
  for (size_t i = 0; i < n; ++i) {
    t[i] = (p[(i + 1) % n] - p[i]).normalized();
    a[i] = p[i] + distance[i] * Vec2(-t[i].y(), t[i].x());
  }
  for (size_t i = 0; i < n; ++i) {
    const size_t h = (i + n - 1) % n;
    const double c = cross2(t[h], t[i]);
    if (std::abs(c) < 1e-12) {
      q[i] = p[i] + 0.5 * (distance[h] + distance[i]) * Vec2(-t[i].y(), t[i].x());  // a straight corner
    } else {
      q[i] = a[h] + t[h] * (cross2(a[i] - a[h], t[i]) / c);
    }
  }
  // Every edge keeps its direction and a length, and the remainder does not cross itself:
  // else the offset would change the polygon's shape (an edge event), which this does not follow.
  for (size_t i = 0; i < n; ++i)
    if (!((q[(i + 1) % n] - q[i]).dot(t[i]) > eps)) {
      std::ostringstream m;
      m << "Setback: setting the edges back this far makes edge " << i
        << " vanish (the polygon is too small for these distances)";
      error = m.str();
      return false;
    }
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segmentsMeet(q[i], q[(i + 1) % n], q[j], q[(j + 1) % n])) {
        error = "Setback: the remainder would cross itself at these distances (edges " + std::to_string(i) + " and " +
                std::to_string(j) + ")";
        return false;
      }
    }
  return true;
}

bool setbackDistanceForArea(const FlatPolygon& polygon, const std::vector<bool>& selected, double area,
                            double& distance, std::string& error) {
  const std::vector<Vec2>& p = polygon.ring;
  double extent = 0;
  for (const Vec2& x : p) extent = std::max(extent, (x - p[0]).norm());
  const double eps = 1e-9 * std::max(extent, 1.0);
  const double whole = twiceRingArea(p) / 2;
  if (!(area > 0) || !(area < whole)) {
    std::ostringstream m;
    m << "setbackToArea: the area " << area << " must be above 0 and below the polygon's " << whole;
    error = m.str();
    return false;
  }
  // The remainder shrinks as the distance grows: bisect for the distance that leaves `area`.
  auto remainderArea = [&](double d) {
    std::vector<double> dist(p.size(), 0.0);
    for (size_t i = 0; i < p.size(); ++i) dist[i] = selected[i] ? d : 0.0;
    std::vector<Vec2> q;
    std::string ignored;
    return insetCorners(p, dist, eps, q, ignored) ? twiceRingArea(q) / 2 : -1.0;  // -1: too far
  };
  double lo = 0, hi = extent;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (remainderArea(mid) >= area ? lo : hi) = mid;
  }
  const double reached = remainderArea(lo);
  if (!(std::abs(reached - area) <= 1e-6 * std::max(1.0, area))) {
    std::ostringstream m;
    m << "setbackToArea: the area " << area << " cannot be reached by setting these edges back (the least is "
      << reached << " before an edge vanishes)";
    error = m.str();
    return false;
  }
  distance = lo;
  return true;
}

bool setback(const FlatPolygon& polygon, const std::vector<double>& distance, const std::vector<int>& group,
             const std::vector<bool>& merged, GeometryArena& arena, std::vector<Part>& pieces,
             std::vector<int>& pieceGroup, std::vector<Part>& remainder, std::string& error) {
  pieces.clear();
  pieceGroup.clear();
  remainder.clear();
  const std::vector<Vec2>& p = polygon.ring;
  const size_t n = p.size();
  double extent = 0;
  for (const Vec2& q : p) extent = std::max(extent, (q - p[0]).norm());
  const double eps = 1e-9 * std::max(extent, 1.0);
  // Negative distances move edges outward (CGA's offset(+d)); one direction for all edges.
  bool inward = false, outward = false;
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(distance[i])) {
      std::ostringstream m;
      m << "Setback: the distance " << distance[i] << " of edge " << i << " is not a finite number";
      error = m.str();
      return false;
    }
    inward |= distance[i] > 0, outward |= distance[i] < 0;
  }
  if (inward && outward) {
    error = "Setback: some edges would move in and others out (distances of both signs)";
    return false;
  }
  std::vector<Vec2> q;
  if (!insetCorners(p, distance, eps, q, error)) return false;
  auto setBack = [&](size_t i) { return group[i] >= 0 && distance[i] != 0; };
  auto add = [&](const std::vector<Vec2>& ring, const std::vector<std::vector<Vec2>>& holes, int g) {
    const std::vector<Vec2> r = distinct(ring, eps);
    if (r.size() < 3 || !(std::abs(twiceRingArea(r)) > eps * eps)) return true;
    Part part;
    if (!planePart(polygon, r, holes, arena, part, error)) return false;
    pieces.push_back(part);
    pieceGroup.push_back(g);
    return true;
  };
  // All edges one merged group: a ring around the remainder.
  bool around = n > 0 && setBack(0) && merged[size_t(group[0])];
  for (size_t i = 0; i < n && around; ++i) around = setBack(i) && group[i] == group[0];
  if (around) {
    // The band around the remainder (inward) or around the polygon (outward).
    const std::vector<Vec2>& outer = outward ? q : p;
    const std::vector<Vec2>& inner = outward ? p : q;
    std::vector<Vec2> hole(inner.rbegin(), inner.rend());
    if (!add(outer, {hole}, group[0])) return false;
  } else {
    for (size_t i = 0; i < n; ++i) {
      if (!setBack(i)) continue;
      const int g = group[i];
      const size_t h = (i + n - 1) % n;
      size_t last = i;
      if (merged[size_t(g)]) {
        if (setBack(h) && group[h] == g) continue;  // inside a run that starts earlier
        while (setBack((last + 1) % n) && group[(last + 1) % n] == g && (last + 1) % n != i) last = (last + 1) % n;
      }
      std::vector<Vec2> band;
      for (size_t k = i;; k = (k + 1) % n) {
        band.push_back(p[k]);
        if (k == last) break;
      }
      band.push_back(p[(last + 1) % n]);
      for (size_t k = (last + 1) % n;; k = (k + n - 1) % n) {
        band.push_back(q[k]);
        if (k == i) break;
      }
      if (!add(band, {}, g)) return false;
    }
  }
  std::vector<Vec2> rest = distinct(q, eps);
  if (rest.size() >= 3 && twiceRingArea(rest) > eps * eps) {
    Part part;
    if (!planePart(polygon, rest, {}, arena, part, error)) return false;
    remainder.push_back(part);
  }
  return true;
}

namespace {

bool insideRing(const std::vector<Vec2>& ring, const Vec2& x, double eps) {
  // On the boundary counts as inside.
  const size_t n = ring.size();
  bool in = false;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = ring[j];
    const Vec2& b = ring[i];
    const Vec2 ab = b - a;
    const double len = ab.norm();
    if (len > 0 && std::abs(cross2(ab, x - a)) / len <= eps && (x - a).dot(ab) >= -eps && (x - b).dot(ab) <= eps)
      return true;
    if ((a.y() > x.y()) != (b.y() > x.y()) && x.x() < a.x() + (x.y() - a.y()) * ab.x() / ab.y()) in = !in;
  }
  return in;
}

std::vector<double> gridLines(std::vector<double> v, double eps) {
  const double lo = *std::min_element(v.begin(), v.end()), hi = *std::max_element(v.begin(), v.end());
  constexpr int kSteps = 128;
  for (int k = 1; k < kSteps; ++k) v.push_back(lo + (hi - lo) * k / kSteps);
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || x - out.back() > eps) out.push_back(x);
  return out;
}

struct Rect {
  double area = 0, u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

// The largest rectangle with sides along u and v inside the ring (given in u, v).
Rect largestRectangle(const std::vector<Vec2>& ring, double eps) {
  std::vector<double> us, vs;
  for (const Vec2& p : ring) us.push_back(p.x()), vs.push_back(p.y());
  us = gridLines(us, eps);
  vs = gridLines(vs, eps);
  const size_t C = us.size() - 1, R = vs.size() - 1;
  std::vector<char> ok(R * C);
  for (size_t r = 0; r < R; ++r)
    for (size_t c = 0; c < C; ++c) {
      const Vec2 centre(0.5 * (us[c] + us[c + 1]), 0.5 * (vs[r] + vs[r + 1]));
      bool in = insideRing(ring, centre, eps);
      for (size_t k = 0; k < 4 && in; ++k) in = insideRing(ring, Vec2(us[c + (k & 1)], vs[r + (k >> 1)]), eps);
      ok[r * C + c] = in;
    }
  Rect best;
  std::vector<char> column(C);
  for (size_t r0 = 0; r0 < R; ++r0) {
    std::fill(column.begin(), column.end(), 1);
    for (size_t r1 = r0; r1 < R; ++r1) {
      const double h = vs[r1 + 1] - vs[r0];
      for (size_t c = 0; c < C; ++c) column[c] = column[c] && ok[r1 * C + c];
      for (size_t c = 0; c < C;) {
        if (!column[c]) {
          ++c;
          continue;
        }
        size_t e = c;
        while (e < C && column[e]) ++e;
        const double area = (us[e] - us[c]) * h;
        if (area > best.area * (1 + 1e-12)) best = {area, us[c], us[e], vs[r0], vs[r1 + 1]};
        c = e;
      }
    }
  }
  return best;
}

}  // namespace

bool innerRectangle(const FlatPolygon& polygon, bool alongEdge, GeometryArena& arena, Part& out, std::string& error) {
  const std::vector<Vec2>& p = polygon.ring;
  double extent = 0;
  for (const Vec2& q : p) extent = std::max(extent, (q - p[0]).norm());
  const double eps = 1e-9 * std::max(extent, 1.0);
  std::vector<Vec2> directions{Vec2(1, 0)};
  if (alongEdge) {
    directions.clear();
    for (size_t i = 0; i < p.size(); ++i) directions.push_back((p[(i + 1) % p.size()] - p[i]).normalized());
  }
  Rect best;
  Vec2 bestDir(1, 0);
  for (const Vec2& d : directions) {
    const Vec2 e(-d.y(), d.x());
    std::vector<Vec2> turned;
    for (const Vec2& q : p) turned.emplace_back(q.dot(d), q.dot(e));
    const Rect r = largestRectangle(turned, eps);
    if (r.area > best.area * (1 + 1e-9)) best = r, bestDir = d;
  }
  if (!(best.area > 0)) {
    error = "innerRectangle: no rectangle fits in the polygon";
    return false;
  }
  const Vec2 e(-bestDir.y(), bestDir.x());
  out = Part{};
  out.scope = polygon.scope;
  const Vec3 x = polygon.scope.X() * bestDir.x() + polygon.scope.Y() * bestDir.y();
  out.scope.axes.col(0) = x;
  out.scope.axes.col(1) = polygon.scope.Z().cross(x);
  out.scope.axes.col(2) = polygon.scope.Z();
  const Vec2 corner = bestDir * best.u0 + e * best.v0;
  out.scope.P = polygon.scope.toWorld(Vec3(corner.x(), corner.y(), 0.0));
  out.scope.S = Vec3(best.u1 - best.u0, best.v1 - best.v0, 0.0);
  out.geom = arena.addPolygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)});
  if (polygon.groundFace) asGroundFace(out, out.scope.X(), arena);
  return true;
}

}  // namespace fgsg::rt::cga
