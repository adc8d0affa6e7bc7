#include "runtime/atlas/chart_splitting.h"

#include <algorithm>
#include <limits>
#include <queue>

namespace fgsg::rt::atlas {

namespace {

// Shortest distances over the faces labelled `label`, from several sources at once; each
// face learns its nearest source (ties: the lower source index). Returns the farthest
// face reached (ties: the lowest-numbered).
int growFrom(const surface::SurfaceMesh& mesh, const std::vector<Vec3>& centroids,
             const std::vector<int>& faces, const std::vector<int>& faceLabel, int label,
             const std::vector<int>& sources, SplitScratch& s) {
  constexpr double kUnreached = std::numeric_limits<double>::infinity();
  for (int f : faces) s.distance[f] = kUnreached, s.source[f] = -1;
  struct Step {
    double distance;
    int source, face;
    bool operator>(const Step& o) const {
      if (distance != o.distance) return distance > o.distance;
      return source != o.source ? source > o.source : face > o.face;
    }
  };
  std::priority_queue<Step, std::vector<Step>, std::greater<Step>> front;
  for (int i = 0; i < int(sources.size()); ++i) {
    s.distance[sources[i]] = 0;
    s.source[sources[i]] = i;
    front.push({0.0, i, sources[i]});
  }
  int farthest = sources.front();
  double farthestDistance = 0;
  while (!front.empty()) {
    const Step st = front.top();
    front.pop();
    // Stale entries: the face was reached sooner (or as soon, from a lower source) since.
    if (st.distance > s.distance[st.face] || st.source != s.source[st.face]) continue;
    if (st.distance > farthestDistance ||
        (st.distance == farthestDistance && st.face < farthest)) {
      farthest = st.face;
      farthestDistance = st.distance;
    }
    for (int g : mesh.neighbours[st.face]) {
      if (g < 0 || faceLabel[g] != label) continue;
      const double d = st.distance + (centroids[g] - centroids[st.face]).norm();
      if (d < s.distance[g] || (d == s.distance[g] && st.source < s.source[g])) {
        s.distance[g] = d;
        s.source[g] = st.source;
        front.push({d, st.source, g});
      }
    }
  }
  return farthest;
}

}  // namespace

std::array<std::vector<int>, 2> bisectChart(const surface::SurfaceMesh& mesh,
                                            const std::vector<Vec3>& centroids,
                                            const std::vector<int>& faces,
                                            const std::vector<int>& faceLabel, SplitScratch& scratch,
                                            const std::vector<int>& aroundHole) {
  scratch.distance.resize(mesh.faces.size());
  scratch.source.resize(mesh.faces.size());
  const int label = faceLabel[faces[0]];
  int a = -1, b = -1;
  if (!aroundHole.empty()) {
    // The hole's lowest face, and the face along the hole farthest from it.
    a = *std::min_element(aroundHole.begin(), aroundHole.end());
    growFrom(mesh, centroids, faces, faceLabel, label, {a}, scratch);
    for (int f : aroundHole)
      if (f != a && (b < 0 || scratch.distance[f] > scratch.distance[b] ||
                     (scratch.distance[f] == scratch.distance[b] && f < b)))
        b = f;
  }
  if (b < 0) {
    // Two sweeps find two faces about as far apart as the chart allows.
    const int first = *std::min_element(faces.begin(), faces.end());
    a = growFrom(mesh, centroids, faces, faceLabel, label, {first}, scratch);
    b = growFrom(mesh, centroids, faces, faceLabel, label, {a}, scratch);
  }
  growFrom(mesh, centroids, faces, faceLabel, label, {a, b}, scratch);
  std::array<std::vector<int>, 2> halves;
  for (int f : faces) halves[scratch.source[f] == 1 ? 1 : 0].push_back(f);
  for (auto& h : halves) std::sort(h.begin(), h.end());
  return halves;
}

}  // namespace fgsg::rt::atlas
