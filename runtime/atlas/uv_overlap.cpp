#include "runtime/atlas/uv_overlap.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::atlas {

namespace {

struct Box {
  Vec2 lo, hi;
};

Box boundsOf(const std::array<Vec2, 3>& t) {
  return {t[0].cwiseMin(t[1]).cwiseMin(t[2]), t[0].cwiseMax(t[1]).cwiseMax(t[2])};
}

// Separating axis test: convex polygons whose interiors are disjoint can be separated by
// a line along one of their edges, so the six edge normals decide.
bool overlap(const std::array<Vec2, 3>& a, const std::array<Vec2, 3>& b, double tolerance) {
  for (const auto* t : {&a, &b})
    for (int k = 0; k < 3; ++k) {
      const Vec2 e = (*t)[(k + 1) % 3] - (*t)[k];
      const Vec2 axis(-e.y(), e.x());
      const double slack = tolerance * axis.norm();
      double aLo = INFINITY, aHi = -INFINITY, bLo = INFINITY, bHi = -INFINITY;
      for (int i = 0; i < 3; ++i) {
        const double pa = axis.dot(a[i]), pb = axis.dot(b[i]);
        aLo = std::min(aLo, pa), aHi = std::max(aHi, pa);
        bLo = std::min(bLo, pb), bHi = std::max(bHi, pb);
      }
      if (aHi <= bLo + slack || bHi <= aLo + slack) return false;
    }
  return true;
}

// A point inside both overlapping triangles, for messages: the centroid of whichever
// triangle's centroid lies in the other, else the midpoint of the centroids.
Vec2 commonPoint(const std::array<Vec2, 3>& a, const std::array<Vec2, 3>& b) {
  auto inside = [](const std::array<Vec2, 3>& t, const Vec2& p) {
    double s[3];
    for (int k = 0; k < 3; ++k) {
      const Vec2 e = t[(k + 1) % 3] - t[k], d = p - t[k];
      s[k] = e.x() * d.y() - e.y() * d.x();
    }
    return (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0);
  };
  const Vec2 ca = (a[0] + a[1] + a[2]) / 3, cb = (b[0] + b[1] + b[2]) / 3;
  if (inside(b, ca)) return ca;
  if (inside(a, cb)) return cb;
  return (ca + cb) / 2;
}

}  // namespace

UVOverlap findUVOverlap(const std::vector<std::array<Vec2, 3>>& triangles, double tolerance) {
  UVOverlap result;
  const int n = int(triangles.size());
  if (n < 2) return result;
  std::vector<Box> boxes(n);
  Box all{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY)};
  double extentSum = 0;
  for (int i = 0; i < n; ++i) {
    boxes[i] = boundsOf(triangles[i]);
    all.lo = all.lo.cwiseMin(boxes[i].lo);
    all.hi = all.hi.cwiseMax(boxes[i].hi);
    extentSum += (boxes[i].hi - boxes[i].lo).maxCoeff();
  }
  // Cells about as large as a typical triangle, at most a few per triangle in all.
  const Vec2 size = (all.hi - all.lo).cwiseMax(Vec2::Constant(1e-300));
  const double maxCells = 4.0 * n;
  double cell = std::max({extentSum / n, std::sqrt(size.x() * size.y() / maxCells),
                          std::max(size.x(), size.y()) / maxCells});
  int nx = 1, ny = 1;
  auto cellX = [&](double x) { return std::clamp(int((x - all.lo.x()) / cell), 0, nx - 1); };
  auto cellY = [&](double y) { return std::clamp(int((y - all.lo.y()) / cell), 0, ny - 1); };
  // Triangles per cell, as one compressed list (each triangle in every cell its box meets).
  // Long thin triangles can meet many cells: coarser cells then keep the list short.
  std::vector<size_t> start;
  for (;;) {
    nx = std::max(1, int(std::ceil(size.x() / cell)));
    ny = std::max(1, int(std::ceil(size.y() / cell)));
    start.assign(size_t(nx) * ny + 1, 0);
    for (const Box& b : boxes)
      for (int y = cellY(b.lo.y()); y <= cellY(b.hi.y()); ++y)
        for (int x = cellX(b.lo.x()); x <= cellX(b.hi.x()); ++x) ++start[size_t(y) * nx + x + 1];
    for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    if (start.back() <= 32 * size_t(n) || (nx == 1 && ny == 1)) break;
    cell *= 2;
  }
  std::vector<int> members(start.back());
  {
    std::vector<size_t> fill(start.begin(), start.end() - 1);
    for (int i = 0; i < n; ++i)
      for (int y = cellY(boxes[i].lo.y()); y <= cellY(boxes[i].hi.y()); ++y)
        for (int x = cellX(boxes[i].lo.x()); x <= cellX(boxes[i].hi.x()); ++x)
          members[fill[size_t(y) * nx + x]++] = i;
  }

  for (size_t c = 0; c + 1 < start.size(); ++c) {
    const int cx = int(c % nx), cy = int(c / nx);
    for (size_t p = start[c]; p < start[c + 1]; ++p)
      for (size_t q = p + 1; q < start[c + 1]; ++q) {
        const int i = members[p], j = members[q];
        const Box &a = boxes[i], &b = boxes[j];
        if (a.hi.x() <= b.lo.x() || b.hi.x() <= a.lo.x() || a.hi.y() <= b.lo.y() ||
            b.hi.y() <= a.lo.y())
          continue;
        // Each pair is tested once: in the cell holding the low corner of where the two
        // boxes meet.
        if (cellX(std::max(a.lo.x(), b.lo.x())) != cx || cellY(std::max(a.lo.y(), b.lo.y())) != cy)
          continue;
        if (overlap(triangles[i], triangles[j], tolerance)) {
          result.first = std::min(i, j);
          result.second = std::max(i, j);
          result.where = commonPoint(triangles[i], triangles[j]);
          return result;
        }
      }
  }
  return result;
}

}  // namespace fgsg::rt::atlas
