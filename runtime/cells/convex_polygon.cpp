// Convex polygon clipping (convex_polygon.h).
#include "runtime/cells/convex_polygon.h"

#include "runtime/cells/occupancy.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::cells {

double signedArea(const Polygon2& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2 &u = p[i], &w = p[(i + 1) % p.size()];
    a += u.x() * w.y() - u.y() * w.x();
  }
  return 0.5 * a;
}

void clipHalfPlaneInto(const Polygon2& p, const Vec2& n, double c, Polygon2& out) {
  out.clear();
  if (p.empty()) return;
  // Corners that coincide (a vertex on the line) are one corner: a point equal to the
  // last one kept is not kept again.
  auto keep = [&](const Vec2& q) {
    if (out.empty() || q != out.back()) out.push_back(q);
  };
  double da = n.dot(p[0]) - c;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2 &a = p[i], &b = p[(i + 1) % p.size()];
    const double db = n.dot(b) - c;
    if (da <= 0) keep(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) keep(a + (b - a) * (da / (da - db)));
    da = db;
  }
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  if (out.size() < 3) out.clear();
}

Polygon2 clipHalfPlane(const Polygon2& p, const Vec2& n, double c) {
  Polygon2 out;
  out.reserve(p.size() + 1);
  clipHalfPlaneInto(p, n, c, out);
  return out;
}

namespace {
// Side i of a counter-clockwise polygon as the half-plane n . x <= c of its inside.
void sideLine(const Polygon2& p, size_t i, Vec2& n, double& c) {
  const Vec2 &a = p[i], &b = p[(i + 1) % p.size()];
  n = Vec2(b.y() - a.y(), a.x() - b.x());  // outward (to the right of a -> b)
  c = n.dot(a);
}
}  // namespace

Polygon2 intersectConvex(const Polygon2& p, const Polygon2& clip) {
  Polygon2 out = p, next;
  out.reserve(p.size() + clip.size()), next.reserve(p.size() + clip.size());
  for (size_t i = 0; i < clip.size() && !out.empty(); ++i) {
    Vec2 n;
    double c;
    sideLine(clip, i, n, c);
    if (n.squaredNorm() == 0) continue;
    clipHalfPlaneInto(out, n, c, next);
    out.swap(next);
  }
  return out;
}

namespace {
// The first side of `hole` that `p` does not lie wholly inside, and whether `p` lies wholly
// outside it; hole.size() when `p` lies inside every side.
size_t firstSideNotHolding(const Polygon2& p, const Polygon2& hole, bool& whollyOutside) {
  for (size_t i = 0; i < hole.size(); ++i) {
    Vec2 n;
    double c;
    sideLine(hole, i, n, c);
    if (n.squaredNorm() == 0) continue;
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec2& q : p) {
      const double d = n.dot(q) - c;  // the clip's own arithmetic
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
    if (hi <= 0) continue;
    whollyOutside = lo >= 0;
    return i;
  }
  return hole.size();
}
}  // namespace

bool holeMisses(const Polygon2& p, const Polygon2& hole) {
  bool outside = false;
  return firstSideNotHolding(p, hole, outside) < hole.size() && outside;
}

std::vector<Polygon2> subtractConvex(const Polygon2& p, const Polygon2& hole, double minArea) {
  std::vector<Polygon2> out;
  // Most holes only touch `p` (a neighbouring cell's claim). A side that `p` lies wholly
  // inside cuts nothing off; at the first side it does not, lying wholly outside it means
  // the loop below makes all of `p` its first piece and leaves of `rest` only a line (no
  // area: every later piece is dropped); lying inside every side, every piece is a line.
  bool whollyOutside = false;
  const size_t first = firstSideNotHolding(p, hole, whollyOutside);
  if (first == hole.size()) return out;
  if (whollyOutside) {
    Vec2 n;
    double c;
    sideLine(hole, first, n, c);
    Polygon2 piece = clipHalfPlane(p, -n, -c);
    if (!piece.empty() && signedArea(piece) > minArea) out.push_back(std::move(piece));
    return out;
  }
  Polygon2 rest = p, inside;
  for (size_t i = 0; i < hole.size() && !rest.empty(); ++i) {
    Vec2 n;
    double c;
    sideLine(hole, i, n, c);
    if (n.squaredNorm() == 0) continue;
    Polygon2 outside = clipHalfPlane(rest, -n, -c);
    if (!outside.empty() && signedArea(outside) > minArea) out.push_back(std::move(outside));
    clipHalfPlaneInto(rest, n, c, inside);
    rest.swap(inside);
  }
  return out;  // what is left of `rest` lies inside the hole
}

Polygon2 convexUnion(const std::vector<Polygon2>& pieces, double areaTol) {
  if (pieces.size() == 1) return pieces[0];
  std::vector<Vec2> all;
  double sum = 0;
  for (const Polygon2& q : pieces) all.insert(all.end(), q.begin(), q.end()), sum += signedArea(q);
  Polygon2 hull = convexHull(std::move(all));
  if (hull.size() < 3 || std::abs(signedArea(hull) - sum) > areaTol) return {};
  return hull;
}

Polygon2 insetConvex(const Polygon2& p, double by) {
  Polygon2 out = p;
  for (size_t i = 0; i < p.size() && !out.empty(); ++i) {
    Vec2 n;
    double c;
    sideLine(p, i, n, c);
    const double len = n.norm();
    if (len == 0) continue;
    out = clipHalfPlane(out, n / len, c / len - by);
  }
  return out;
}

SolidFaces clipSolid(const SolidFaces& s, const Eigen::Vector3d& n, double c, double tol) {
  using V3 = Eigen::Vector3d;
  SolidFaces out;
  std::vector<V3> cap;  // the corners the plane leaves: the new face's
  for (const std::vector<V3>& f : s) {
    std::vector<V3> kept;
    for (size_t i = 0; i < f.size(); ++i) {
      const V3 &a = f[i], &b = f[(i + 1) % f.size()];
      const double da = n.dot(a) - c, db = n.dot(b) - c;
      if (da <= tol) kept.push_back(a);
      if (std::abs(da) <= tol) cap.push_back(a);
      if ((da < -tol && db > tol) || (da > tol && db < -tol)) {
        const V3 q = a + (b - a) * (da / (da - db));
        kept.push_back(q), cap.push_back(q);
      }
    }
    if (kept.size() >= 3) out.push_back(std::move(kept));
  }
  if (out.empty()) return out;
  // The cap: its corners without repeats, counter-clockwise about n (outward: the solid
  // keeps n . x <= c).
  std::vector<V3> corners;
  for (const V3& q : cap)
    if (std::none_of(corners.begin(), corners.end(), [&](const V3& k) { return (k - q).norm() <= tol; }))
      corners.push_back(q);
  if (corners.size() >= 3) {
    V3 mid = V3::Zero();
    for (const V3& q : corners) mid += q;
    mid /= double(corners.size());
    const V3 e1 = (std::abs(n.x()) < 0.9 ? V3::UnitX() : V3::UnitY()).cross(n).normalized(), e2 = n.cross(e1);
    std::sort(corners.begin(), corners.end(), [&](const V3& a, const V3& b) {
      return std::atan2((a - mid).dot(e2), (a - mid).dot(e1)) < std::atan2((b - mid).dot(e2), (b - mid).dot(e1));
    });
    out.push_back(std::move(corners));
  }
  return out;
}

}  // namespace fgsg::rt::cells
