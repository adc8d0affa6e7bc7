// A disk-shaped chart made into a piece of an atlas: parametrized (conformal), turned so
// that it is not mirrored, checked not to fold or overlap itself, scaled so that its flat
// area equals its surface area (every chart then has the same texel density once packing
// applies one common factor: marching measures lengths in texels), and turned to its
// smallest bounding rectangle.
#pragma once

#include "runtime/atlas/chart_mesh.h"
#include "runtime/atlas/chart_packing.h"

namespace fgsg::rt::atlas {

// False when the chart cannot be laid flat in one piece as it is (the solve fails, a
// triangle folds or collapses, or the layout overlaps itself): split it and try again.
bool flattenChart(const surface::SurfaceMesh& mesh, const ChartMesh& chart, FlatChart& out);

}  // namespace fgsg::rt::atlas
