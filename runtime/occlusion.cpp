#include "runtime/occlusion.h"

#include <cmath>

namespace fgsg::rt {
namespace {

// Relative shrink of a query box, so faces that merely touch are not occluding.
constexpr double kTouchTolerance = 1e-6;

}  // namespace

OcclusionIndex::Box OcclusionIndex::makeBox(const Scope& s, double shrink) {
  Box b;
  b.axes = s.axes;
  // Scope sizes may be negative after mirroring; the box is the same either way.
  const Vec3 size = s.S.cwiseAbs();
  b.half = (0.5 * size - Vec3::Constant(shrink).cwiseProduct(size.cwiseMax(1.0))).cwiseMax(0.0);
  b.center = s.P + s.axes * (0.5 * s.S);
  const Vec3 extent = s.axes.cwiseAbs() * b.half;
  b.lo = b.center - extent;
  b.hi = b.center + extent;
  return b;
}

void OcclusionIndex::add(const Scope& box) { boxes_.push_back(makeBox(box, 0.0)); }

bool OcclusionIndex::intersects(const Box& a, const Box& b) {
  const Mat3 R = a.axes.transpose() * b.axes;  // b's axes in a's frame
  const Vec3 t = a.axes.transpose() * (b.center - a.center);
  const Mat3 absR = R.cwiseAbs().array() + 1e-12;
  for (int i = 0; i < 3; ++i)
    if (std::abs(t[i]) > a.half[i] + absR.row(i).dot(b.half)) return false;
  for (int j = 0; j < 3; ++j)
    if (std::abs(t.dot(R.col(j))) > absR.col(j).dot(a.half) + b.half[j]) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = a.half[i1] * absR(i2, j) + a.half[i2] * absR(i1, j);
      const double rb = b.half[j1] * absR(i, j2) + b.half[j2] * absR(i, j1);
      if (std::abs(t[i2] * R(i1, j) - t[i1] * R(i2, j)) > ra + rb) return false;
    }
  return true;
}

bool OcclusionIndex::contains(const Box& outer, const Box& inner) {
  for (int c = 0; c < 8; ++c) {
    Vec3 corner = inner.center;
    for (int k = 0; k < 3; ++k) corner += ((c >> k) & 1 ? 1.0 : -1.0) * inner.half[k] * inner.axes.col(k);
    const Vec3 local = outer.axes.transpose() * (corner - outer.center);
    for (int k = 0; k < 3; ++k)
      if (std::abs(local[k]) > outer.half[k] + 1e-12) return false;
  }
  return true;
}

Occlusion OcclusionIndex::test(const Scope& query) const {
  const Box q = makeBox(query, kTouchTolerance);
  bool any = false;
  for (const Box& b : boxes_) {
    if ((q.hi.array() < b.lo.array()).any() || (q.lo.array() > b.hi.array()).any()) continue;
    if (!intersects(q, b)) continue;
    if (contains(b, q)) return Occlusion::Full;
    any = true;
  }
  return any ? Occlusion::Partial : Occlusion::None;
}

}  // namespace fgsg::rt
