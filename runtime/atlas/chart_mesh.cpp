#include "runtime/atlas/chart_mesh.h"

#include <algorithm>
#include <numeric>

namespace fgsg::rt::atlas {

namespace {

struct CornerSets {  // union-find over the chart's face corners
  std::vector<int> parent;
  explicit CornerSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

ChartMesh extractChart(const surface::SurfaceMesh& mesh, std::vector<int> faces,
                       const std::vector<int>& faceLabel, ChartMeshScratch& scratch) {
  ChartMesh chart;
  std::sort(faces.begin(), faces.end());
  chart.faces = std::move(faces);
  const int n = int(chart.faces.size());
  if (n == 0) return chart;
  const int label = faceLabel[chart.faces[0]];
  scratch.positionInChart.resize(mesh.faces.size());
  for (int i = 0; i < n; ++i) scratch.positionInChart[chart.faces[i]] = i;
  auto inChart = [&](int g) { return g >= 0 && faceLabel[g] == label; };

  // Corners around a vertex that are joined by an edge inside the chart belong to one fan,
  // and one fan is one chart vertex. Faces joined that way also make the chart connected.
  CornerSets corners(3 * size_t(n));
  CornerSets pieces(n);
  for (int i = 0; i < n; ++i) {
    const int f = chart.faces[i];
    for (int k = 0; k < 3; ++k) {
      const int g = mesh.neighbours[f][k];
      if (!inChart(g)) {
        chart.boundaryEdges.push_back({3 * i + k, 3 * i + (k + 1) % 3});  // corners for now
        chart.boundaryFace.push_back(i);
        continue;
      }
      if (g < f) continue;  // each inner edge once
      const int j = scratch.positionInChart[g];
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      corners.unite(3 * i + k, 3 * j + mesh.cornerOf(g, a));
      corners.unite(3 * i + (k + 1) % 3, 3 * j + mesh.cornerOf(g, b));
      pieces.unite(i, j);
    }
  }
  for (int i = 1; i < n; ++i)
    if (pieces.find(i) != pieces.find(0)) chart.connected = false;

  std::vector<int> vertexOfCorner(3 * size_t(n), -1);
  chart.triangles.resize(n);
  for (int c = 0; c < 3 * n; ++c) {
    const int root = corners.find(c);  // the smallest corner of its set: already numbered
    if (vertexOfCorner[root] < 0) {
      vertexOfCorner[root] = chart.vertexCount();
      chart.meshVertex.push_back(mesh.faces[chart.faces[c / 3]][c % 3]);
    }
    vertexOfCorner[c] = vertexOfCorner[root];
    chart.triangles[c / 3][c % 3] = vertexOfCorner[c];
  }
  for (auto& e : chart.boundaryEdges) e = {vertexOfCorner[e[0]], vertexOfCorner[e[1]]};

  // A fan that is not a full ring has one boundary edge leaving it and one arriving, so
  // the boundary edges chain into loops.
  const int nv = chart.vertexCount();
  std::vector<int> leaving(nv, -1);  // the boundary edge leaving each vertex
  for (int e = 0; e < int(chart.boundaryEdges.size()); ++e) leaving[chart.boundaryEdges[e][0]] = e;
  chart.boundaryLoop.assign(chart.boundaryEdges.size(), -1);
  for (int e = 0; e < int(chart.boundaryEdges.size()); ++e) {
    if (chart.boundaryLoop[e] >= 0) continue;
    for (int walk = e; walk >= 0 && chart.boundaryLoop[walk] < 0; walk = leaving[chart.boundaryEdges[walk][1]])
      chart.boundaryLoop[walk] = chart.boundaryLoops;
    ++chart.boundaryLoops;
  }
  return chart;
}

}  // namespace fgsg::rt::atlas
