#include "runtime/atlas/chart_segmentation.h"

#include <cmath>
#include <queue>

namespace fgsg::rt::atlas {

std::vector<Vec3> faceCentroids(const surface::SurfaceMesh& mesh) {
  std::vector<Vec3> centroids(mesh.faces.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& t = mesh.faces[f];
    centroids[f] = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
  }
  return centroids;
}

Segmentation growCharts(const surface::SurfaceMesh& mesh, const std::vector<Vec3>& centroids,
                        double maxNormalDeviationDegrees) {
  const int nf = int(mesh.faces.size());
  const double cosLimit = std::cos(maxNormalDeviationDegrees * M_PI / 180.0);
  Segmentation seg;
  seg.faceChart.assign(nf, -1);

  // Faces turned away by a finished chart, in the order they were met: the next seeds.
  std::vector<int> turnedAway;
  size_t nextTurnedAway = 0;
  int nextByIndex = 0;
  // Distance from the current seed, valid where grownBy == the current chart.
  std::vector<double> distance(nf, 0.0);
  std::vector<int> grownBy(nf, -1);
  struct Step {
    double distance;
    int face;
    bool operator>(const Step& o) const {
      return distance != o.distance ? distance > o.distance : face > o.face;
    }
  };
  std::priority_queue<Step, std::vector<Step>, std::greater<Step>> front;

  for (;;) {
    int seed = -1;
    while (seed < 0 && nextTurnedAway < turnedAway.size()) {
      const int f = turnedAway[nextTurnedAway++];
      if (seg.faceChart[f] < 0) seed = f;
    }
    while (seed < 0 && nextByIndex < nf) {
      if (seg.faceChart[nextByIndex] < 0) seed = nextByIndex;
      ++nextByIndex;
    }
    if (seed < 0) break;
    const int chart = seg.chartCount++;
    const Vec3 seedNormal = mesh.faceNormals[seed];
    grownBy[seed] = chart;
    distance[seed] = 0;
    front.push({0.0, seed});
    while (!front.empty()) {
      const Step s = front.top();
      front.pop();
      if (seg.faceChart[s.face] >= 0 || s.distance > distance[s.face]) continue;
      seg.faceChart[s.face] = chart;
      for (int g : mesh.neighbours[s.face]) {
        if (g < 0 || seg.faceChart[g] >= 0) continue;
        if (mesh.faceNormals[g].dot(seedNormal) < cosLimit) {
          turnedAway.push_back(g);
          continue;
        }
        const double d = s.distance + (centroids[g] - centroids[s.face]).norm();
        if (grownBy[g] != chart || d < distance[g]) {
          grownBy[g] = chart;
          distance[g] = d;
          front.push({d, g});
        }
      }
    }
  }
  return seg;
}

}  // namespace fgsg::rt::atlas
