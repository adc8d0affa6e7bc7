#include "runtime/marching/indirection_pointers.h"

#include <nanoflann.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <limits>

namespace fgsg::rt::marching {

namespace {

// The inner-border texels' surface points, as nanoflann reads them.
struct BorderCloud {
  std::vector<Eigen::Vector3f> points;
  size_t kdtree_get_point_count() const { return points.size(); }
  float kdtree_get_pt(size_t i, size_t d) const { return points[i][int(d)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};
using BorderTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, BorderCloud>,
                                                       BorderCloud, 3, uint32_t>;

// A nanoflann result set keeping the nearest border texel that is not on the pointer's
// own side of its chart's border.
struct NearestAcross {
  const std::vector<int32_t>& texelOf;  // border point -> texel index
  const std::vector<int32_t>& chart;    // texel -> chart
  int size, fromX, fromY, ownChart;
  float best = std::numeric_limits<float>::max();
  uint32_t bestPoint = ~0u;

  float worstDist() const { return best; }
  bool full() const { return bestPoint != ~0u; }
  bool addPoint(float distance, uint32_t point) {
    if (distance >= best) return true;
    const int t = texelOf[point];
    if (chart[t] == ownChart) {
      const int dx = t % size - fromX, dy = t / size - fromY;
      if (dx * dx + dy * dy < kOwnSideTexels * kOwnSideTexels) return true;
    }
    best = distance;
    bestPoint = point;
    return true;
  }
};

constexpr std::array<std::array<int, 2>, 8> kRing = {
    {{-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}}};

}  // namespace

int chartsAround(const std::vector<int32_t>& chart, int size, int x, int y, std::array<int, 8>& found) {
  int n = 0;
  for (const auto& [dx, dy] : kRing) {
    const int nx = x + dx, ny = y + dy;
    if (nx < 0 || ny < 0 || nx >= size || ny >= size) continue;
    const int c = chart[size_t(ny) * size + nx];
    int at = n;  // insertion into the ascending list, skipping a chart already in it
    while (at > 0 && found[at - 1] > c) --at;
    if (c < 0 || (at > 0 && found[at - 1] == c)) continue;
    for (int k = n; k > at; --k) found[k] = found[k - 1];
    found[at] = c;
    ++n;
  }
  return n;
}

PointerLayout findIndirectionPointers(const std::vector<ImageTriangle>& triangles, int size,
                                      const std::vector<int32_t>& face, const std::vector<int32_t>& chart,
                                      const std::vector<Eigen::Vector3f>& position) {
  const size_t texels = size_t(size) * size;
  auto inside = [size](int x, int y) { return x >= 0 && y >= 0 && x < size && y < size; };

  PointerLayout out;
  out.count.assign(texels, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, size, 16), [&](const auto& rows) {
    std::array<int, 8> found;
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < size; ++x)
        if (face[size_t(y) * size + x] < 0) out.count[size_t(y) * size + x] = uint8_t(chartsAround(chart, size, x, y, found));
  });
  std::vector<uint32_t> start(texels + 1, 0);
  for (size_t i = 0; i < texels; ++i) start[i + 1] = start[i] + out.count[i];
  out.pointers.assign(start[texels], IndirectionPointer{});

  // Inner-border texels: inner texels with a neighbour that is not of their chart;
  // found row by row in parallel, gathered in row order (the tree is then the same
  // whatever the scheduling).
  std::vector<std::vector<int32_t>> borderRows(size);
  tbb::parallel_for(tbb::blocked_range<int>(0, size, 16), [&](const auto& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < size; ++x) {
        const size_t i = size_t(y) * size + x;
        if (chart[i] < 0) continue;
        for (const auto& [dx, dy] : kRing)
          if (!inside(x + dx, y + dy) || chart[size_t(y + dy) * size + (x + dx)] != chart[i]) {
            borderRows[y].push_back(int32_t(i));
            break;
          }
      }
  });
  BorderCloud cloud;
  std::vector<int32_t> texelOf;
  for (const auto& row : borderRows)
    for (int32_t i : row) {
      cloud.points.push_back(position[i]);
      texelOf.push_back(i);
    }
  BorderTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));

  tbb::parallel_for(tbb::blocked_range<int>(0, size, 8), [&](const auto& rows) {
    std::array<int, 8> found;
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < size; ++x) {
        const size_t i = size_t(y) * size + x;
        if (out.count[i] == 0) continue;
        const int n = chartsAround(chart, size, x, y, found);
        for (int k = 0; k < n; ++k) {
          IndirectionPointer& ptr = out.pointers[start[i] + k];
          ptr.chart = found[k];
          Eigen::Vector3f mean = Eigen::Vector3f::Zero();
          double reach = 0;
          int around = 0;
          for (const auto& [dx, dy] : kRing) {
            if (!inside(x + dx, y + dy)) continue;
            const size_t j = size_t(y + dy) * size + (x + dx);
            if (chart[j] != ptr.chart) continue;
            mean += position[j];
            reach = std::max(reach, triangles[face[j]].texelLength);
            ++around;
          }
          mean /= float(around);
          NearestAcross nearest{texelOf, chart, size, x, y, ptr.chart};
          if (cloud.points.empty()) continue;
          tree.findNeighbors(nearest, mean.data(), nanoflann::SearchParams());
          if (!nearest.full()) continue;
          const int target = texelOf[nearest.bestPoint];
          reach = kSeamReachTexels * (reach + triangles[face[target]].texelLength);
          if (double(nearest.best) <= reach * reach) ptr.target = target;
        }
      }
  });
  return out;
}

}  // namespace fgsg::rt::marching
