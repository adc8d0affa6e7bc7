#include "runtime/atlas/chart_cleanup.h"

#include <algorithm>
#include <numeric>

namespace fgsg::rt::atlas {

namespace {

// Moves teeth and holes over to the chart around them.
void smoothBoundaries(const surface::SurfaceMesh& mesh, std::vector<int>& chart, std::vector<int>& size) {
  constexpr int kMaxPasses = 8;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    bool moved = false;
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
      const auto& n = mesh.neighbours[f];
      int majority = -1;
      for (int a = 0; a < 3 && majority < 0; ++a)
        for (int b = a + 1; b < 3; ++b)
          if (n[a] >= 0 && n[b] >= 0 && chart[n[a]] == chart[n[b]] && chart[n[a]] != chart[f]) {
            majority = chart[n[a]];
            break;
          }
      if (majority < 0 || size[chart[f]] == 1) continue;
      --size[chart[f]];
      ++size[majority];
      chart[f] = majority;
      moved = true;
    }
    if (!moved) break;
  }
}

// Splits every chart into its connected pieces (over shared edges) and numbers them by
// their lowest face. Returns the count.
int relabelConnected(const surface::SurfaceMesh& mesh, std::vector<int>& chart) {
  const int nf = int(mesh.faces.size());
  std::vector<int> piece(nf, -1), stack;
  int count = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (piece[seed] >= 0) continue;
    piece[seed] = count;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int g : mesh.neighbours[f])
        if (g >= 0 && piece[g] < 0 && chart[g] == chart[f]) {
          piece[g] = count;
          stack.push_back(g);
        }
    }
    ++count;
  }
  chart = std::move(piece);
  return count;
}

// Merges slivers into the neighbour they share the most boundary length with.
void mergeSlivers(const surface::SurfaceMesh& mesh, std::vector<int>& chart, int chartCount) {
  const int nf = int(mesh.faces.size());
  std::vector<double> area(chartCount, 0);
  std::vector<std::vector<int>> faces(chartCount);
  for (int f = 0; f < nf; ++f) {
    area[chart[f]] += mesh.faceAreas[f];
    faces[chart[f]].push_back(f);
  }
  const double total = std::accumulate(area.begin(), area.end(), 0.0);
  const double sliver = kSliverFraction * total / chartCount;
  std::vector<int> order(chartCount);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return area[a] != area[b] ? area[a] < area[b] : a < b; });
  std::vector<int> into(chartCount);  // where a merged chart went (follow to the end)
  std::iota(into.begin(), into.end(), 0);
  auto current = [&](int c) {
    while (into[c] != c) c = into[c];
    return c;
  };
  std::vector<std::pair<int, double>> shared;  // neighbouring chart, boundary length
  for (int c : order) {
    if (area[c] >= sliver) break;  // ascending: the rest are larger (merges only grow charts)
    if (into[c] != c) continue;
    shared.clear();
    for (int f : faces[c])
      for (int k = 0; k < 3; ++k) {
        const int g = mesh.neighbours[f][k];
        if (g < 0) continue;
        const int d = current(chart[g]);
        if (d == c) continue;
        const double length =
            (mesh.vertices[mesh.faces[f][(k + 1) % 3]] - mesh.vertices[mesh.faces[f][k]]).norm();
        auto it = std::find_if(shared.begin(), shared.end(), [&](const auto& s) { return s.first == d; });
        if (it == shared.end())
          shared.push_back({d, length});
        else
          it->second += length;
      }
    if (shared.empty()) continue;  // a component of its own
    const auto best = std::max_element(shared.begin(), shared.end(), [](const auto& a, const auto& b) {
      return a.second != b.second ? a.second < b.second : a.first > b.first;
    });
    const int d = best->first;
    into[c] = d;
    area[d] += area[c];
    faces[d].insert(faces[d].end(), faces[c].begin(), faces[c].end());
    faces[c].clear();
  }
  for (int f = 0; f < nf; ++f) chart[f] = current(chart[f]);
}

}  // namespace

void cleanUpCharts(const surface::SurfaceMesh& mesh, Segmentation& segmentation) {
  std::vector<int>& chart = segmentation.faceChart;
  std::vector<int> size(segmentation.chartCount, 0);
  for (int c : chart) ++size[c];
  smoothBoundaries(mesh, chart, size);
  segmentation.chartCount = relabelConnected(mesh, chart);
  mergeSlivers(mesh, chart, segmentation.chartCount);
  segmentation.chartCount = relabelConnected(mesh, chart);
}

}  // namespace fgsg::rt::atlas
