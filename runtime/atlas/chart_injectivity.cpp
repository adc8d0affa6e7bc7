#include "runtime/atlas/chart_injectivity.h"

#include "runtime/atlas/uv_geometry.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::atlas {

namespace {

// The fans: the angles around each vertex add up to one turn inside, less on the boundary.
bool fansTurnOnce(const ChartMesh& chart, const std::vector<Vec2>& uv) {
  std::vector<double> turn(chart.vertexCount(), 0.0);
  for (const auto& t : chart.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = uv[t[(k + 1) % 3]] - uv[t[k]], b = uv[t[(k + 2) % 3]] - uv[t[k]];
      turn[t[k]] += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  std::vector<uint8_t> onBoundary(chart.vertexCount(), 0);
  for (const auto& e : chart.boundaryEdges) onBoundary[e[0]] = 1;
  for (int v = 0; v < chart.vertexCount(); ++v)
    // Inside: exactly 2 pi when the fan turns once, 4 pi or more when it wraps around twice.
    if (turn[v] >= (onBoundary[v] ? 2 * M_PI : 3 * M_PI)) return false;
  return true;
}

// The boundary: no two edges that are not neighbours along it meet. Edges are binned into
// a grid of cells about an edge long.
bool boundaryIsSimple(const ChartMesh& chart, const std::vector<Vec2>& uv) {
  const auto& edges = chart.boundaryEdges;
  const int n = int(edges.size());
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  double length = 0;
  for (const auto& e : edges) {
    lo = lo.cwiseMin(uv[e[0]]), hi = hi.cwiseMax(uv[e[0]]);
    length += (uv[e[1]] - uv[e[0]]).norm();
  }
  const Vec2 size = (hi - lo).cwiseMax(Vec2::Constant(1e-300));
  const double cell = std::max({length / n, size.x() / n, size.y() / n, 1e-300});
  const int nx = std::max(1, int(std::ceil(size.x() / cell))), ny = std::max(1, int(std::ceil(size.y() / cell)));
  auto cx = [&](double x) { return std::clamp(int((x - lo.x()) / cell), 0, nx - 1); };
  auto cy = [&](double y) { return std::clamp(int((y - lo.y()) / cell), 0, ny - 1); };
  std::vector<std::pair<size_t, int>> entries;  // (cell, edge), sorted by cell
  for (int i = 0; i < n; ++i) {
    const Vec2 &a = uv[edges[i][0]], &b = uv[edges[i][1]];
    for (int y = cy(std::min(a.y(), b.y())); y <= cy(std::max(a.y(), b.y())); ++y)
      for (int x = cx(std::min(a.x(), b.x())); x <= cx(std::max(a.x(), b.x())); ++x)
        entries.push_back({size_t(y) * nx + x, i});
  }
  std::sort(entries.begin(), entries.end());
  for (size_t first = 0; first < entries.size();) {
    size_t last = first;
    while (last < entries.size() && entries[last].first == entries[first].first) ++last;
    for (size_t i = first; i < last; ++i)
      for (size_t j = i + 1; j < last; ++j) {
        const auto &e = edges[entries[i].second], &f = edges[entries[j].second];
        if (e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1]) continue;  // neighbours
        if (segmentsMeet(uv[e[0]], uv[e[1]], uv[f[0]], uv[f[1]])) return false;
      }
    first = last;
  }
  return true;
}

}  // namespace

bool layoutIsInjective(const ChartMesh& chart, const std::vector<Vec2>& uv) {
  return fansTurnOnce(chart, uv) && boundaryIsSimple(chart, uv);
}

}  // namespace fgsg::rt::atlas
