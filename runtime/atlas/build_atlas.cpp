// buildAtlas: charts grown by normal cone, merged where two fit one cone, cleaned up
// (teeth, holes, slivers); then every chart either laid flat or split in two until all
// are (single faces always can be); then packing.
#include "runtime/atlas/atlas.h"

#include "runtime/atlas/chart_cleanup.h"
#include "runtime/atlas/chart_flattening.h"
#include "runtime/atlas/chart_merging.h"
#include "runtime/atlas/chart_mesh.h"
#include "runtime/atlas/chart_packing.h"
#include "runtime/atlas/chart_segmentation.h"
#include "runtime/atlas/chart_splitting.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace fgsg::rt::atlas {

namespace {

// The faces along the shortest boundary loop but the longest (the outer one, most likely):
// a cut through that hole removes it at the cost of one more chart.
std::vector<int> facesAlongInnerLoop(const surface::SurfaceMesh& mesh, const ChartMesh& chart) {
  std::vector<double> length(chart.boundaryLoops, 0.0);
  for (size_t e = 0; e < chart.boundaryEdges.size(); ++e) {
    const auto& edge = chart.boundaryEdges[e];
    length[chart.boundaryLoop[e]] +=
        (mesh.vertices[chart.meshVertex[edge[1]]] - mesh.vertices[chart.meshVertex[edge[0]]]).norm();
  }
  const int outer = int(std::max_element(length.begin(), length.end()) - length.begin());
  int inner = -1;
  for (int l = 0; l < chart.boundaryLoops; ++l)
    if (l != outer && (inner < 0 || length[l] < length[inner])) inner = l;
  std::vector<int> faces;
  for (size_t e = 0; e < chart.boundaryEdges.size(); ++e)
    if (chart.boundaryLoop[e] == inner) faces.push_back(chart.faces[chart.boundaryFace[e]]);
  return faces;
}

}  // namespace

bool buildAtlas(const surface::SurfaceMesh& mesh, const AtlasOptions& options, Atlas& out,
                std::string& error) {
  out = Atlas{};
  if (!checkAtlasOptions(options, error)) return false;
  const size_t nf = mesh.faces.size();
  if (nf == 0) {
    error = "atlas: the surface has no faces";
    return false;
  }
  if (mesh.neighbours.size() != nf || mesh.faceNormals.size() != nf || mesh.faceAreas.size() != nf) {
    error = "atlas: the surface's topology is not built (SurfaceMesh::buildTopology)";
    return false;
  }

  const std::vector<Vec3> centroids = faceCentroids(mesh);
  Segmentation segmentation = growCharts(mesh, centroids, options.maxNormalDeviation);
  mergeCompatibleCharts(mesh, options.maxNormalDeviation, segmentation);
  cleanUpCharts(mesh, segmentation);

  // Charts waiting to be flattened, each with a label of its own in `label`. They are
  // flattened in waves, in parallel (each chart on its own); the ones that fail are split
  // in order and make the next wave, so the result does not depend on the threads.
  std::vector<int> label = segmentation.faceChart;
  std::vector<std::vector<int>> wave(segmentation.chartCount);
  for (size_t f = 0; f < nf; ++f) wave[label[f]].push_back(int(f));
  int nextLabel = segmentation.chartCount;
  tbb::enumerable_thread_specific<ChartMeshScratch> meshScratch;
  SplitScratch splitScratch;
  std::vector<FlatChart> flat;
  while (!wave.empty()) {
    std::vector<FlatChart> laid(wave.size());
    std::vector<uint8_t> done(wave.size(), 0);
    std::vector<std::vector<int>> hole(wave.size());  // where to cut a chart with holes
    tbb::parallel_for(tbb::blocked_range<size_t>(0, wave.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) {
        const ChartMesh chart = extractChart(mesh, wave[i], label, meshScratch.local());
        done[i] = chart.isDisk() && flattenChart(mesh, chart, laid[i]);
        if (!done[i] && chart.boundaryLoops > 1) hole[i] = facesAlongInnerLoop(mesh, chart);
      }
    });
    std::vector<std::vector<int>> next;
    for (size_t i = 0; i < wave.size(); ++i) {
      if (done[i]) {
        flat.push_back(std::move(laid[i]));
        continue;
      }
      if (wave[i].size() == 1) {  // validated surfaces have no such face
        error = "atlas: face " + std::to_string(wave[i][0]) + " cannot be laid flat (degenerate?)";
        return false;
      }
      auto halves = bisectChart(mesh, centroids, wave[i], label, splitScratch, hole[i]);
      for (int f : halves[1]) label[f] = nextLabel;
      ++nextLabel;
      next.push_back(std::move(halves[0]));
      next.push_back(std::move(halves[1]));
    }
    wave = std::move(next);
  }
  // Chart numbers by their lowest face, whatever order splitting produced them in.
  std::sort(flat.begin(), flat.end(),
            [](const FlatChart& a, const FlatChart& b) { return a.faces.front() < b.faces.front(); });
  return packCharts(flat, nf, options, /*allowRotation=*/true, out, error);
}

}  // namespace fgsg::rt::atlas
