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

Polygon2 clipHalfPlane(const Polygon2& p, const Vec2& n, double c) {
  Polygon2 out;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2 &a = p[i], &b = p[(i + 1) % p.size()];
    const double da = n.dot(a) - c, db = n.dot(b) - c;
    if (da <= 0) out.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  // Corners that coincide (a vertex on the line) are one corner.
  Polygon2 kept;
  for (const Vec2& q : out)
    if (kept.empty() || q != kept.back()) kept.push_back(q);
  while (kept.size() > 1 && kept.front() == kept.back()) kept.pop_back();
  if (kept.size() < 3) kept.clear();
  return kept;
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
  Polygon2 out = p;
  for (size_t i = 0; i < clip.size() && !out.empty(); ++i) {
    Vec2 n;
    double c;
    sideLine(clip, i, n, c);
    if (n.squaredNorm() == 0) continue;
    out = clipHalfPlane(out, n, c);
  }
  return out;
}

std::vector<Polygon2> subtractConvex(const Polygon2& p, const Polygon2& hole, double minArea) {
  std::vector<Polygon2> out;
  Polygon2 rest = p;
  for (size_t i = 0; i < hole.size() && !rest.empty(); ++i) {
    Vec2 n;
    double c;
    sideLine(hole, i, n, c);
    if (n.squaredNorm() == 0) continue;
    Polygon2 outside = clipHalfPlane(rest, -n, -c);
    if (!outside.empty() && signedArea(outside) > minArea) out.push_back(std::move(outside));
    rest = clipHalfPlane(rest, n, c);
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

}  // namespace fgsg::rt::cells
