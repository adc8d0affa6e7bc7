#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fgsg::rt::cga {
namespace {

constexpr double kConvexTol = 1e-9;  // vertices this far outside a face plane still count as inside
constexpr double kCornerTol = 1e-9;  // unit-square corner test

// Removes consecutive duplicate points (clipping emits a point on the plane twice).
void removeDuplicates(Polygon3& p) {
  Polygon3 out;
  out.reserve(p.size());
  for (const Vec3& q : p)
    if (out.empty() || (q - out.back()).cwiseAbs().maxCoeff() > kPlaneTol) out.push_back(q);
  while (out.size() > 1 && (out.front() - out.back()).cwiseAbs().maxCoeff() <= kPlaneTol)
    out.pop_back();
  p.swap(out);
}

// Sutherland-Hodgman against one plane: keeps the side where sign * (c[axis] - value) >= 0.
// Intersections are snapped onto the plane so caps and re-normalisation see exact values.
Polygon3 clipPolygon(const Polygon3& in, int axis, double value, double sign) {
  Polygon3 out;
  out.reserve(in.size() + 2);
  const std::size_t n = in.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = in[i];
    const Vec3& b = in[(i + 1) % n];
    const double da = sign * (a[axis] - value);
    const double db = sign * (b[axis] - value);
    const bool inA = da >= -kPlaneTol;
    const bool inB = db >= -kPlaneTol;
    if (inA) out.push_back(a);
    if (inA != inB) {
      const double t = std::clamp(da / (da - db), 0.0, 1.0);
      Vec3 p = a + t * (b - a);
      p[axis] = value;
      out.push_back(p);
    }
  }
  removeDuplicates(out);
  return out;
}

// The convex hull (monotone chain) of points on the plane c[axis] = const, counter-clockwise
// about +axis: the two in-plane axes (a1, a2) follow axis cyclically so e_a1 x e_a2 = e_axis.
Polygon3 convexHullOnPlane(Polygon3 pts, int axis) {
  if (pts.size() < 3) return {};
  const int a1 = (axis + 1) % 3;
  const int a2 = (axis + 2) % 3;
  std::sort(pts.begin(), pts.end(), [&](const Vec3& p, const Vec3& q) {
    return p[a1] < q[a1] || (p[a1] == q[a1] && p[a2] < q[a2]);
  });
  auto cross = [&](const Vec3& o, const Vec3& p, const Vec3& q) {
    return (p[a1] - o[a1]) * (q[a2] - o[a2]) - (p[a2] - o[a2]) * (q[a1] - o[a1]);
  };
  // Strict turn with a tolerance drops collinear and duplicate points.
  constexpr double kTurnTol = kPlaneTol * kPlaneTol;
  Polygon3 hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= kTurnTol) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= kTurnTol) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k > 0 ? k - 1 : 0);
  return hull;
}

enum class HalfSpace { Empty, Unchanged, Cut };

// Keeps sign * (c[axis] - value) >= 0 of every face; a convex solid gets a cap on the plane.
HalfSpace clipHalfSpace(LocalGeometry& g, int axis, double value, double sign) {
  double dmin = std::numeric_limits<double>::infinity();
  double dmax = -dmin;
  for (const Polygon3& f : g.faces)
    for (const Vec3& p : f) {
      const double d = sign * (p[axis] - value);
      dmin = std::min(dmin, d);
      dmax = std::max(dmax, d);
    }
  // Touching the plane from outside leaves nothing with area or volume.
  if (!(dmax > kPlaneTol)) return HalfSpace::Empty;
  if (dmin >= -kPlaneTol) return HalfSpace::Unchanged;

  std::vector<Polygon3> kept;
  kept.reserve(g.faces.size() + 1);
  for (const Polygon3& f : g.faces) {
    Polygon3 c = clipPolygon(f, axis, value, sign);
    if (c.size() >= 3 && 0.5 * newellNormal(c).norm() > kMinArea) kept.push_back(std::move(c));
  }
  if (g.kind == GeomKind::Polyhedron && g.convex && !kept.empty()) {
    Polygon3 onPlane;
    for (const Polygon3& f : kept)
      for (const Vec3& p : f)
        if (std::abs(p[axis] - value) <= kPlaneTol) onPlane.push_back(p);
    Polygon3 cap = convexHullOnPlane(std::move(onPlane), axis);
    if (cap.size() >= 3 && 0.5 * newellNormal(cap).norm() > kMinArea) {
      // The hull turns about +axis; the cap's outward normal is -sign * axis.
      if (sign > 0) std::reverse(cap.begin(), cap.end());
      kept.push_back(std::move(cap));
    }
  }
  g.faces.swap(kept);
  return g.faces.empty() ? HalfSpace::Empty : HalfSpace::Cut;
}

bool isConvexSolid(const std::vector<Polygon3>& faces) {
  for (const Polygon3& f : faces) {
    const Vec3 n = newellNormal(f);
    const double len = n.norm();
    if (len <= kMinArea) continue;  // a degenerate face bounds nothing
    const Vec3 u = n / len;
    for (const Polygon3& g : faces)
      for (const Vec3& p : g)
        if ((p - f[0]).dot(u) > kConvexTol) return false;
  }
  return true;
}

}  // namespace

LocalGeometry loadGeometry(const GeometryArena& arena, const GeomRef& ref) {
  LocalGeometry g;
  g.kind = ref.kind;
  if (ref.kind == GeomKind::Polygon) {
    const Vec3* p = arena.polygon(ref);
    g.faces.emplace_back(p, p + ref.count);
  } else if (ref.kind == GeomKind::Polyhedron) {
    g.faces.reserve(ref.count);
    for (uint32_t i = 0; i < ref.count; ++i) {
      const GeometryArena::Face& f = arena.face(ref, i);
      const Vec3* p = arena.facePoints(f);
      g.faces.emplace_back(p, p + f.count);
    }
    g.convex = isConvexSolid(g.faces);
  }
  return g;
}

GeomRef storeGeometry(GeometryArena& arena, const LocalGeometry& g) {
  if (g.kind == GeomKind::Polygon) return arena.addPolygon(g.faces.front());
  return arena.addPolyhedron(g.faces);
}

bool isUnitSquare(const Vec3* pts, std::size_t count) {
  if (count != 4) return false;
  unsigned corners = 0;  // bit x + 2y per corner seen
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec3& p = pts[i];
    const bool x0 = std::abs(p.x()) <= kCornerTol, x1 = std::abs(p.x() - 1) <= kCornerTol;
    const bool y0 = std::abs(p.y()) <= kCornerTol, y1 = std::abs(p.y() - 1) <= kCornerTol;
    if (!(x0 || x1) || !(y0 || y1) || std::abs(p.z()) > kCornerTol) return false;
    corners |= 1u << ((x1 ? 1 : 0) + (y1 ? 2 : 0));
  }
  // Four distinct corners, counter-clockwise: a positive area rules out crossed orders.
  return corners == 0xF && newellNormal(pts, 4).z() > 0;
}

bool isSlabInvariant(const GeometryArena& arena, const GeomRef& ref) {
  switch (ref.kind) {
    case GeomKind::Box:
    case GeomKind::Edge:
      return true;
    case GeomKind::Polygon:
      return isUnitSquare(arena.polygon(ref), ref.count);
    case GeomKind::Polyhedron:
      return false;
  }
  return false;
}

bool clipToSlab(LocalGeometry& g, int axis, double lo, double hi) {
  if (hi < lo) return false;
  if (clipHalfSpace(g, axis, lo, 1.0) == HalfSpace::Empty) return false;
  return clipHalfSpace(g, axis, hi, -1.0) != HalfSpace::Empty;
}

void renormalise(LocalGeometry& g, int axis, double lo, double hi) {
  const double len = hi - lo;
  for (Polygon3& f : g.faces)
    for (Vec3& p : f) p[axis] = len > 0 ? std::clamp((p[axis] - lo) / len, 0.0, 1.0) : 0.0;
}

Vec3 newellNormal(const Vec3* pts, std::size_t count) {
  Vec3 n = Vec3::Zero();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3& a = pts[i];
    const Vec3& b = pts[(i + 1) % count];
    n.x() += (a.y() - b.y()) * (a.z() + b.z());
    n.y() += (a.z() - b.z()) * (a.x() + b.x());
    n.z() += (a.x() - b.x()) * (a.y() + b.y());
  }
  return n;
}

const std::vector<Polygon3>& unitBoxFaces() {
  static const std::vector<Polygon3> faces = {
      {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},  // front  +Z
      {{1, 0, 1}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}},  // right  +X
      {{1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}},  // back   -Z
      {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}},  // left   -X
      {{0, 1, 1}, {1, 1, 1}, {1, 1, 0}, {0, 1, 0}},  // top    +Y
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},  // bottom -Y
  };
  return faces;
}

Scope solidFrameOnPolygon(const Scope& polygonScope) {
  Scope s = polygonScope;  // keeps what is not geometry: the colour
  s.axes.col(0) = polygonScope.X();
  s.axes.col(1) = polygonScope.Z();
  s.axes.col(2) = -polygonScope.Y();
  s.P = polygonScope.P + polygonScope.Y() * polygonScope.S.y();
  s.S = Vec3(polygonScope.S.x(), 0.0, polygonScope.S.y());
  return s;
}

namespace {

bool lexLess(const Vec3& a, const Vec3& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

}  // namespace

std::vector<bool> bridgeEdges(const Polygon3& pts) {
  const std::size_t n = pts.size();
  std::vector<std::pair<Vec3, Vec3>> edges;  // (from, to), sorted to find reverses
  for (std::size_t i = 0; i < n; ++i) edges.emplace_back(pts[i], pts[(i + 1) % n]);
  auto less = [](const std::pair<Vec3, Vec3>& a, const std::pair<Vec3, Vec3>& b) {
    return lexLess(a.first, b.first) || (a.first == b.first && lexLess(a.second, b.second));
  };
  std::vector<std::pair<Vec3, Vec3>> sorted = edges;
  std::sort(sorted.begin(), sorted.end(), less);
  std::vector<bool> bridge(n, false);
  for (std::size_t i = 0; i < n; ++i)
    bridge[i] = std::binary_search(sorted.begin(), sorted.end(), std::make_pair(edges[i].second, edges[i].first), less);
  return bridge;
}

std::vector<Polygon3> ringsOf(const Polygon3& pts) {
  const std::vector<bool> bridge = bridgeEdges(pts);
  if (std::find(bridge.begin(), bridge.end(), true) == bridge.end()) return {pts};
  // Each ring edge left, by its start point; a ring is traced from any unused edge by
  // following the edge that starts where the last one ends.
  const std::size_t n = pts.size();
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < n; ++i)
    if (!bridge[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lexLess(pts[a], pts[b]); });
  std::vector<bool> used(n, false);
  std::vector<Polygon3> rings;
  for (std::size_t start : order) {
    if (used[start]) continue;
    Polygon3 ring;
    for (std::size_t e = start; e < n && !used[e];) {
      used[e] = true;
      ring.push_back(pts[e]);
      const Vec3& end = pts[(e + 1) % n];
      auto it = std::lower_bound(order.begin(), order.end(), end,
                                 [&](std::size_t a, const Vec3& p) { return lexLess(pts[a], p); });
      e = n;
      for (; it != order.end() && pts[*it] == end; ++it)
        if (!used[*it]) {
          e = *it;
          break;
        }
    }
    if (ring.size() >= 3) rings.push_back(std::move(ring));
  }
  std::sort(rings.begin(), rings.end(), [](const Polygon3& a, const Polygon3& b) {
    return newellNormal(a).norm() > newellNormal(b).norm();
  });
  return rings;
}

}  // namespace fgsg::rt::cga
