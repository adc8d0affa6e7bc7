// buildAtlas: segmentation, then every chart either laid flat or split in two until all
// are (single faces always can be), then packing.
#include "runtime/atlas/atlas.h"

#include "runtime/atlas/chart_cleanup.h"
#include "runtime/atlas/chart_flattening.h"
#include "runtime/atlas/chart_mesh.h"
#include "runtime/atlas/chart_packing.h"
#include "runtime/atlas/chart_segmentation.h"
#include "runtime/atlas/chart_splitting.h"

#include <algorithm>

namespace fgsg::rt::atlas {

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
  cleanUpCharts(mesh, segmentation);

  // Charts waiting to be flattened, each with a label of its own in `label`.
  std::vector<int> label = segmentation.faceChart;
  std::vector<std::vector<int>> pending(segmentation.chartCount);
  for (size_t f = 0; f < nf; ++f) pending[label[f]].push_back(int(f));
  int nextLabel = segmentation.chartCount;
  ChartMeshScratch meshScratch;
  SplitScratch splitScratch;
  std::vector<FlatChart> flat;
  for (size_t next = 0; next < pending.size(); ++next) {
    std::vector<int> faces = std::move(pending[next]);
    const ChartMesh chart = extractChart(mesh, faces, label, meshScratch);
    FlatChart laid;
    if (chart.isDisk() && flattenChart(mesh, chart, laid)) {
      flat.push_back(std::move(laid));
      continue;
    }
    if (chart.faces.size() == 1) {  // validated surfaces have no such face
      error = "atlas: face " + std::to_string(chart.faces[0]) + " cannot be laid flat (degenerate?)";
      return false;
    }
    auto halves = bisectChart(mesh, centroids, chart.faces, label, splitScratch);
    for (int f : halves[1]) label[f] = nextLabel;
    ++nextLabel;
    pending.push_back(std::move(halves[0]));
    pending.push_back(std::move(halves[1]));
  }
  // Chart numbers by their lowest face, whatever order splitting produced them in.
  std::sort(flat.begin(), flat.end(),
            [](const FlatChart& a, const FlatChart& b) { return a.faces.front() < b.faces.front(); });
  return packCharts(flat, nf, options, /*allowRotation=*/true, out, error);
}

}  // namespace fgsg::rt::atlas
