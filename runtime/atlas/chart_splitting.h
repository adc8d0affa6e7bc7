// Cutting a chart that cannot be laid flat in one piece (a hole, a handle, several
// boundaries, a parametrization that folds) into two that may: both halves are regions
// grown at the same pace from two faces far apart, so each half is connected and the cut
// runs across the chart's longest extent.
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <array>
#include <vector>

namespace fgsg::rt::atlas {

// Scratch space reused across splits (sized by the mesh; only touched entries are reset).
struct SplitScratch {
  std::vector<double> distance;
  std::vector<int> source;
};

// Splits `faces` (a connected set of at least two faces, all labelled
// faceLabel[faces[0]], distances measured between `centroids`) in two non-empty, connected
// halves, each ascending. Deterministic. With `aroundHole` (the chart's faces along one
// inner boundary loop), the two halves grow from opposite sides of that hole, so the cut
// runs through it and the hole is gone from both; otherwise from the chart's two ends.
std::array<std::vector<int>, 2> bisectChart(const surface::SurfaceMesh& mesh,
                                            const std::vector<Vec3>& centroids,
                                            const std::vector<int>& faces,
                                            const std::vector<int>& faceLabel, SplitScratch& scratch,
                                            const std::vector<int>& aroundHole = {});

}  // namespace fgsg::rt::atlas
