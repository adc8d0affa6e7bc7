#include "runtime/marching/atlas_raster.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

namespace fgsg::rt::marching {

namespace {

// A square must reach this far (texels) into a triangle to count as overlapping it, so
// that a triangle merely touching a texel's side does not claim the texel.
constexpr double kMinOverlap = 1e-6;
constexpr uint64_t kUncovered = ~uint64_t(0);

// A candidate as one word: the squared distance from the texel centre to the face (a
// non-negative float, whose bits order as the values do) above the face number, so that
// one atomic minimum keeps the closest face, and the lowest face among equals.
uint64_t pack(float distanceSquared, int face) {
  uint32_t bits;
  std::memcpy(&bits, &distanceSquared, sizeof bits);
  return (uint64_t(bits) << 32) | uint32_t(face);
}
int packedFace(uint64_t v) { return int(uint32_t(v)); }
bool packedHoldsCentre(uint64_t v) { return (v >> 32) == 0; }

// A face's image triangle as the texel tests need it: its box, and each edge's outward
// unit normal with the edge's offset along it (a point p is inside when
// normal[k] . p <= offset[k] for all k).
struct EdgeTests {
  Vec2 low, high;
  std::array<Vec2, 3> normal;
  std::array<double, 3> offset;

  explicit EdgeTests(const ImageTriangle& t) {
    low = t.corner[0].cwiseMin(t.corner[1]).cwiseMin(t.corner[2]);
    high = t.corner[0].cwiseMax(t.corner[1]).cwiseMax(t.corner[2]);
    for (int k = 0; k < 3; ++k) {
      const Vec2 e = t.corner[(k + 1) % 3] - t.corner[k];
      normal[k] = Vec2(e.y(), -e.x()).normalized();  // counter-clockwise: inside on the left
      offset[k] = normal[k].dot(t.corner[k]);
    }
  }
  // Separating axes: the two image axes and the three edge normals.
  bool overlapsSquare(double x0, double y0) const {
    if (x0 + 1 <= low.x() + kMinOverlap || x0 >= high.x() - kMinOverlap || y0 + 1 <= low.y() + kMinOverlap ||
        y0 >= high.y() - kMinOverlap)
      return false;
    for (int k = 0; k < 3; ++k) {
      const double squareLow = normal[k].x() * x0 + normal[k].y() * y0 + std::min(0.0, normal[k].x()) +
                               std::min(0.0, normal[k].y());
      if (squareLow >= offset[k] - kMinOverlap) return false;
    }
    return true;
  }
  bool holds(const Vec2& p) const {
    for (int k = 0; k < 3; ++k)
      if (normal[k].dot(p) > offset[k]) return false;
    return true;
  }
};

}  // namespace

AtlasRaster rasterizeAtlas(const std::vector<ImageTriangle>& triangles, int size) {
  const size_t texels = size_t(size) * size;
  std::unique_ptr<std::atomic<uint64_t>[]> best(new std::atomic<uint64_t>[texels]);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, texels, 1 << 16), [&](const auto& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) best[i].store(kUncovered, std::memory_order_relaxed);
  });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, triangles.size(), 256), [&](const auto& r) {
    for (size_t f = r.begin(); f < r.end(); ++f) {
      const ImageTriangle& t = triangles[f];
      const EdgeTests tests(t);
      const int x0 = std::max(0, int(std::floor(tests.low.x()))), x1 = std::min(size - 1, int(std::ceil(tests.high.x())) - 1);
      const int y0 = std::max(0, int(std::floor(tests.low.y()))), y1 = std::min(size - 1, int(std::ceil(tests.high.y())) - 1);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          if (!tests.overlapsSquare(x, y)) continue;
          const Vec2 centre(x + 0.5, y + 0.5);
          // A centre outside every triangle keeps a positive distance, however small,
          // so that it never passes for one inside.
          const float d2 = tests.holds(centre)
                               ? 0.0f
                               : std::max(float((t.imagePoint(t.closestBary(centre)) - centre).squaredNorm()),
                                          std::numeric_limits<float>::min());
          const uint64_t candidate = pack(d2, int(f));
          std::atomic<uint64_t>& slot = best[size_t(y) * size + x];
          uint64_t seen = slot.load(std::memory_order_relaxed);
          while (candidate < seen && !slot.compare_exchange_weak(seen, candidate, std::memory_order_relaxed)) {
          }
        }
    }
  });
  AtlasRaster out;
  out.face.assign(texels, -1);
  auto chartOf = [&](uint64_t v) { return v == kUncovered ? -1 : triangles[packedFace(v)].chart; };
  out.conservativeTexels = tbb::parallel_reduce(
      tbb::blocked_range<int>(0, size), size_t(0),
      [&](const tbb::blocked_range<int>& rows, size_t count) {
        for (int y = rows.begin(); y < rows.end(); ++y)
          for (int x = 0; x < size; ++x) {
            const size_t i = size_t(y) * size + x;
            const uint64_t v = best[i].load(std::memory_order_relaxed);
            if (v == kUncovered) continue;
            if (!packedHoldsCentre(v)) {
              // A conservative claim yields to any other chart around it, and two
              // conservative claims of different charts both yield: the rule is
              // symmetric, so the outcome does not depend on the order texels are seen.
              const int chart = chartOf(v);
              bool alone = true;
              for (int dy = -1; dy <= 1 && alone; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                  const int nx = x + dx, ny = y + dy;
                  if (nx < 0 || ny < 0 || nx >= size || ny >= size) continue;
                  const int other = chartOf(best[size_t(ny) * size + nx].load(std::memory_order_relaxed));
                  if (other >= 0 && other != chart) {
                    alone = false;
                    break;
                  }
                }
              if (!alone) continue;
              ++count;
            }
            out.face[i] = packedFace(v);
          }
        return count;
      },
      std::plus<size_t>());
  return out;
}

}  // namespace fgsg::rt::marching
