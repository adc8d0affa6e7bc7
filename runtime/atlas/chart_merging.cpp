#include "runtime/atlas/chart_merging.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace fgsg::rt::atlas {

void mergeCompatibleCharts(const surface::SurfaceMesh& mesh, double maxNormalDeviationDegrees,
                           Segmentation& segmentation) {
  constexpr int kMaxRounds = 16;
  const double cosLimit = std::cos(maxNormalDeviationDegrees * M_PI / 180.0);
  std::vector<int>& chart = segmentation.faceChart;
  const int nf = int(mesh.faces.size());
  for (int round = 0; round < kMaxRounds; ++round) {
    const int count = segmentation.chartCount;
    std::vector<std::vector<int>> faces(count);
    std::vector<Vec3> normalSum(count, Vec3::Zero());
    for (int f = 0; f < nf; ++f) {
      faces[chart[f]].push_back(f);
      normalSum[chart[f]] += mesh.faceAreas[f] * mesh.faceNormals[f];
    }
    auto meanNormal = [&](int c) {
      const double len = normalSum[c].norm();
      return len > 0 ? Vec3(normalSum[c] / len) : Vec3::UnitZ();
    };
    // Neighbouring pairs, most alike first.
    std::vector<std::pair<int, int>> pairs;
    for (int f = 0; f < nf; ++f)
      for (int g : mesh.neighbours[f])
        if (g >= 0 && chart[f] < chart[g]) pairs.push_back({chart[f], chart[g]});
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    std::vector<double> alike(pairs.size());
    for (size_t i = 0; i < pairs.size(); ++i) alike[i] = meanNormal(pairs[i].first).dot(meanNormal(pairs[i].second));
    std::vector<size_t> order(pairs.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return std::tie(alike[b], a) < std::tie(alike[a], b);  // descending alike, then pair order
    });

    // Each chart merges at most once per round, so the sums above stay true for it.
    std::vector<uint8_t> touched(count, 0);
    std::vector<int> into(count);
    for (int c = 0; c < count; ++c) into[c] = c;
    bool merged = false;
    for (size_t i : order) {
      const auto [a, b] = pairs[i];
      if (touched[a] || touched[b] || alike[i] < cosLimit) continue;
      const Vec3 mean = (normalSum[a] + normalSum[b]).normalized();
      int seed = -1;
      double best = -2;
      for (int c : {a, b})
        for (int f : faces[c]) {
          const double d = mesh.faceNormals[f].dot(mean);
          if (d > best || (d == best && f < seed)) best = d, seed = f;
        }
      const Vec3& n = mesh.faceNormals[seed];
      bool fits = true;
      for (int c : {a, b})
        for (int f : faces[c])
          if (mesh.faceNormals[f].dot(n) < cosLimit) {
            fits = false;
            break;
          }
      if (!fits) continue;
      touched[a] = touched[b] = 1;
      into[b] = a;
      merged = true;
    }
    if (!merged) break;
    // Renumber by lowest face.
    std::vector<int> number(count, -1);
    int next = 0;
    for (int f = 0; f < nf; ++f) {
      const int c = into[chart[f]];
      if (number[c] < 0) number[c] = next++;
      chart[f] = number[c];
    }
    segmentation.chartCount = next;
  }
}

}  // namespace fgsg::rt::atlas
