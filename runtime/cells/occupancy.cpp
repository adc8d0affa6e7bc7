// Edge and face occupancy maps (occupancy.h).
#include "runtime/cells/occupancy.h"

#include "runtime/cells/feature_param.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fgsg::rt::cells {

namespace {

constexpr int kBuckets = 64;
// Lines across a strip where it must lie on the face: its two borders (nudged inside)
// and three between. Faces here are polygons whose outline is straight between
// vertices, so a strip whose borders and middle lie on the face lies on it unless a
// vertex pokes in between; three inner lines keep that gap below a quarter strip.
constexpr int kStripLines = 5;

// Sorted, merging those that touch within `tol`.
std::vector<Interval> unite(std::vector<Interval> v, double tol) {
  std::sort(v.begin(), v.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  std::vector<Interval> out;
  for (const Interval& i : v) {
    if (!out.empty() && i.lo <= out.back().hi + tol) out.back().hi = std::max(out.back().hi, i.hi);
    else out.push_back(i);
  }
  return out;
}

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

// The parts of [lo, hi] that the sorted disjoint `items` leave uncovered, pieces no
// longer than `minimum` dropped.
std::vector<Interval> gapsIn(const std::vector<Interval>& items, double lo, double hi, double minimum) {
  std::vector<Interval> out;
  double at = lo;
  for (const Interval& i : items) {
    if (i.hi <= at) continue;
    if (i.lo >= hi) break;
    if (i.lo - at > minimum && i.lo > at) out.push_back({at, i.lo});
    at = std::max(at, i.hi);
  }
  if (hi - at > minimum && hi > at) out.push_back({at, hi});
  return out;
}

}  // namespace

void IntervalSet::add(double lo, double hi) {
  if (!(hi > lo)) return;
  items_.push_back({lo, hi});
  items_ = unite(std::move(items_), 0);
}

std::vector<Interval> IntervalSet::gaps(double lo, double hi, double minimum) const {
  return gapsIn(items_, lo, hi, minimum);
}

bool IntervalSet::overlaps(double lo, double hi, double slack) const {
  for (const Interval& i : items_)
    if (std::min(hi, i.hi) - std::max(lo, i.lo) > slack) return true;
  return false;
}

std::vector<Interval> intersect(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  std::vector<Interval> out;
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const double lo = std::max(a[i].lo, b[j].lo), hi = std::min(a[i].hi, b[j].hi);
    if (hi > lo) out.push_back({lo, hi});
    (a[i].hi < b[j].hi ? i : j)++;
  }
  return out;
}

std::vector<Interval> subtract(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  const std::vector<Interval> cut = unite(b, 0);
  std::vector<Interval> out;
  for (const Interval& i : a)
    for (const Interval& g : gapsIn(cut, i.lo, i.hi, 0)) out.push_back(g);
  return out;
}

std::vector<Vec2> convexHull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  if (p.size() < 3) return p;
  std::vector<Vec2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

FaceOccupancy::FaceOccupancy(const FeatureFace& face, const surface::SurfaceMesh& mesh) {
  buckets_.resize(kBuckets);
  if (face.kind == FaceKind::Freeform) return;
  const double seam = face.kind == FaceKind::Cylindrical ? std::numbers::pi * face.radius : 0;
  bool first = true;
  for (int t : face.triangles) {
    std::array<Vec2, 3> tri;
    for (int k = 0; k < 3; ++k) tri[k] = projectOnFace(face, mesh.vertices[mesh.faces[t][k]]);
    if (seam > 0) {  // a triangle across the cylinder's seam at u = +-pi r: unwrap it
      const double span = std::max({tri[0].x(), tri[1].x(), tri[2].x()}) - std::min({tri[0].x(), tri[1].x(), tri[2].x()});
      if (span > seam)
        for (auto& q : tri)
          if (q.x() < 0) q.x() += 2 * seam;
    }
    if (cross(tri[0], tri[1], tri[2]) < 0) std::swap(tri[1], tri[2]);
    for (const Vec2& q : tri) {
      if (first) lo_ = hi_ = q, first = false;
      lo_ = lo_.cwiseMin(q), hi_ = hi_.cwiseMax(q);
    }
    triangles_.push_back(tri);
    for (const Vec2& q : tri) vertexHeights_.push_back(q.y());
    TriangleSides sides;
    sides.lo = sides.hi = tri[0];
    for (int k = 0; k < 3; ++k) {
      const Vec2 &a = tri[k], &b = tri[(k + 1) % 3];
      sides.n[k] = Vec2(b.y() - a.y(), a.x() - b.x());  // outward, as intersectConvex's sides
      sides.c[k] = sides.n[k].dot(a);
      sides.lo = sides.lo.cwiseMin(a), sides.hi = sides.hi.cwiseMax(a);
    }
    sides.proper = cross(tri[0], tri[1], tri[2]) > 0;
    triangleSides_.push_back(sides);
  }
  std::sort(vertexHeights_.begin(), vertexHeights_.end());
  vertexHeights_.erase(std::unique(vertexHeights_.begin(), vertexHeights_.end()), vertexHeights_.end());
  tolerance_ = 1e-9 * std::max((hi_ - lo_).maxCoeff(), 1e-12);
}

std::vector<Interval> FaceOccupancy::insideAt(double v) const {
  std::vector<Interval> spans;
  for (const auto& t : triangles_) {
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < 3; ++k) {
      const Vec2 &a = t[k], &b = t[(k + 1) % 3];
      if ((a.y() - v) * (b.y() - v) > 0) continue;  // both on one side
      if (a.y() == b.y()) {                          // along the line
        lo = std::min({lo, a.x(), b.x()}), hi = std::max({hi, a.x(), b.x()});
        continue;
      }
      const double u = a.x() + (b.x() - a.x()) * (v - a.y()) / (b.y() - a.y());
      lo = std::min(lo, u), hi = std::max(hi, u);
    }
    if (hi > lo) spans.push_back({lo, hi});
  }
  return unite(std::move(spans), tolerance_);
}

std::vector<Interval> FaceOccupancy::insideRuns(double v0, double v1) const {
  if (triangles_.empty() || !(v1 > v0)) return {};
  const double nudge = std::min(tolerance_ * 10, 0.25 * (v1 - v0));
  std::vector<Interval> runs = insideAt(v0 + nudge);
  for (int k = 1; k < kStripLines && !runs.empty(); ++k) {
    const double v = k == kStripLines - 1 ? v1 - nudge : v0 + (v1 - v0) * k / (kStripLines - 1);
    runs = intersect(runs, insideAt(v));
  }
  return runs;
}

int FaceOccupancy::bucketOf(double v) const {
  const double span = hi_.y() - lo_.y();
  if (!(span > 0)) return 0;
  return std::clamp(int((v - lo_.y()) / span * kBuckets), 0, kBuckets - 1);
}

std::vector<Interval> FaceOccupancy::freeRuns(double v0, double v1, double minimum) const {
  std::vector<Interval> inside = insideRuns(v0, v1);
  if (inside.empty()) return inside;
  // The u-extent of every claim within the strip (a claim only touching it is outside).
  std::vector<Interval> taken;
  std::vector<int> seen;
  const double tol = tolerance_;
  for (int b = bucketOf(v0); b <= bucketOf(v1); ++b)
    for (int c : buckets_[b]) {
      if (std::find(seen.begin(), seen.end(), c) != seen.end()) continue;
      seen.push_back(c);
      if (claimHi_[c].y() <= v0 + tol || claimLo_[c].y() >= v1 - tol) continue;
      const auto& poly = claims_[c];
      double lo = INFINITY, hi = -INFINITY;
      for (size_t k = 0; k < poly.size(); ++k) {
        const Vec2 &a = poly[k], &q = poly[(k + 1) % poly.size()];
        if (a.y() >= v0 && a.y() <= v1) lo = std::min(lo, a.x()), hi = std::max(hi, a.x());
        for (double line : {v0, v1})
          if ((a.y() - line) * (q.y() - line) < 0) {
            const double u = a.x() + (q.x() - a.x()) * (line - a.y()) / (q.y() - a.y());
            lo = std::min(lo, u), hi = std::max(hi, u);
          }
      }
      if (hi > lo) taken.push_back({lo, hi});
    }
  const std::vector<Interval> claimed = unite(std::move(taken), 0);
  std::vector<Interval> out;
  for (const Interval& run : inside)
    for (const Interval& g : gapsIn(claimed, run.lo, run.hi, std::max(minimum, tol))) out.push_back(g);
  return out;
}

std::vector<double> FaceOccupancy::breaks(double v0, double v1) const {
  std::vector<double> out;
  const double tol = 1e3 * tolerance_;
  auto within = [&](double v) { return v > v0 + tol && v < v1 - tol; };
  for (auto it = std::upper_bound(vertexHeights_.begin(), vertexHeights_.end(), v0); it != vertexHeights_.end() && *it < v1; ++it)
    if (within(*it)) out.push_back(*it);
  for (int b = bucketOf(v0); b <= bucketOf(v1); ++b)
    for (int c : buckets_[b])
      for (double v : {claimLo_[c].y(), claimHi_[c].y()})
        if (within(v)) out.push_back(v);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(), [&](double a, double b) { return b - a < tol; }), out.end());
  return out;
}

namespace {
void boxOf(const Polygon2& p, Vec2& lo, Vec2& hi) {
  lo = hi = p[0];
  for (const Vec2& q : p) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
}
bool boxesMeet(const Vec2& alo, const Vec2& ahi, const Vec2& blo, const Vec2& bhi) {
  return alo.x() < bhi.x() && blo.x() < ahi.x() && alo.y() < bhi.y() && blo.y() < ahi.y();
}
}  // namespace

std::vector<int> FaceOccupancy::claimsNear(const Vec2& lo, const Vec2& hi) const {
  std::vector<int> out;
  for (int b = bucketOf(lo.y()); b <= bucketOf(hi.y()); ++b)
    for (int c : buckets_[b])
      if (boxesMeet(lo, hi, claimLo_[c], claimHi_[c])) out.push_back(c);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Polygon2> FaceOccupancy::insidePieces(const Polygon2& region, double minArea) const {
  std::vector<Polygon2> out;
  if (region.size() < 3) return out;
  Vec2 lo, hi;
  boxOf(region, lo, hi);
  // intersectConvex(region, triangle) for every triangle the region's box meets, the
  // clips written into two reused buffers.
  Polygon2 piece, next;
  for (const TriangleSides& t : triangleSides_) {
    if (!boxesMeet(lo, hi, t.lo, t.hi) || !t.proper) continue;
    // Wholly (strictly) outside one side: clipping against it keeps no corner and
    // crosses nothing (after an earlier side's clip, at most a rounding sliver, far below
    // every caller's minArea, which is positive).
    bool outside = false;
    for (int k = 0; k < 3 && !outside; ++k) {
      outside = true;
      for (const Vec2& q : region)
        if (!(t.n[k].dot(q) - t.c[k] > 0)) {
          outside = false;
          break;
        }
    }
    if (outside) continue;
    piece.assign(region.begin(), region.end());
    for (int k = 0; k < 3 && !piece.empty(); ++k) {
      if (t.n[k].squaredNorm() == 0) continue;
      clipHalfPlaneInto(piece, t.n[k], t.c[k], next);
      piece.swap(next);
    }
    if (!piece.empty() && signedArea(piece) > minArea) out.push_back(piece);
  }
  return out;
}

std::vector<Polygon2> FaceOccupancy::freePieces(const Polygon2& region, double minArea) const {
  std::vector<Polygon2> pieces = insidePieces(region, minArea);
  if (pieces.empty()) return pieces;
  Vec2 lo, hi;
  boxOf(region, lo, hi);
  std::vector<Polygon2> next;
  for (int c : claimsNear(lo, hi)) {
    next.clear();
    for (Polygon2& p : pieces) {
      Vec2 plo, phi;
      boxOf(p, plo, phi);
      // Pieces are clips' outputs of more than minArea: a claim that misses one (most
      // only touch it) leaves it as it is.
      if (!boxesMeet(plo, phi, claimLo_[c], claimHi_[c]) || holeMisses(p, claims_[c])) {
        next.push_back(std::move(p));
        continue;
      }
      for (Polygon2& q : subtractConvex(p, claims_[c], minArea)) next.push_back(std::move(q));
    }
    pieces.swap(next);
    if (pieces.empty()) break;
  }
  return pieces;
}

std::vector<Interval> FaceOccupancy::reachOf(const std::vector<Polygon2>& pieces, double minimum) const {
  std::vector<Interval> spans;
  for (const Polygon2& p : pieces) {
    Vec2 plo, phi;
    boxOf(p, plo, phi);
    spans.push_back({plo.x(), phi.x()});
  }
  std::vector<Interval> out;
  for (const Interval& i : unite(std::move(spans), tolerance_))
    if (i.length() > minimum) out.push_back(i);
  return out;
}

std::vector<Interval> FaceOccupancy::reachRuns(double v0, double v1, double minimum) const {
  if (triangles_.empty() || !(v1 > v0)) return {};
  const Polygon2 strip{Vec2(lo_.x() - 1, v0), Vec2(hi_.x() + 1, v0), Vec2(hi_.x() + 1, v1), Vec2(lo_.x() - 1, v1)};
  return reachOf(freePieces(strip, minimum * (v1 - v0)), minimum);
}

std::vector<Interval> FaceOccupancy::insideReach(double v0, double v1, double minimum) const {
  if (triangles_.empty() || !(v1 > v0)) return {};
  const Polygon2 strip{Vec2(lo_.x() - 1, v0), Vec2(hi_.x() + 1, v0), Vec2(hi_.x() + 1, v1), Vec2(lo_.x() - 1, v1)};
  return reachOf(insidePieces(strip, minimum * (v1 - v0)), minimum);
}

double FaceOccupancy::area() const {
  double a = 0;
  for (const auto& t : triangles_) a += std::max(0.0, 0.5 * cross(t[0], t[1], t[2]));
  return a;
}

double FaceOccupancy::freeArea() const {
  // Slivers of rounding (below 1e-9 of the face's size squared) are not free space.
  const double minArea = tolerance_ * std::max((hi_ - lo_).maxCoeff(), 1e-12);
  double a = 0;
  for (const auto& t : triangles_) {
    const Polygon2 tri(t.begin(), t.end());
    for (const Polygon2& p : freePieces(tri, minArea)) a += signedArea(p);
  }
  return a;
}

void FaceOccupancy::claim(std::vector<Vec2> points) {
  std::vector<Vec2> hull = convexHull(std::move(points));
  if (hull.size() < 3) return;
  Vec2 lo = hull[0], hi = hull[0];
  for (const Vec2& q : hull) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  // Outside the face's box it claims nothing a generator could ask for.
  if (hi.x() <= lo_.x() || lo.x() >= hi_.x() || hi.y() <= lo_.y() || lo.y() >= hi_.y()) return;
  const int id = int(claims_.size());
  claims_.push_back(std::move(hull));
  claimLo_.push_back(lo), claimHi_.push_back(hi);
  for (int b = bucketOf(lo.y()); b <= bucketOf(hi.y()); ++b) buckets_[b].push_back(id);
}

}  // namespace fgsg::rt::cells
