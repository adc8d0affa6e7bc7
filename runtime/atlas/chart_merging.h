// Region growing from one seed at a time cuts the surface where a seed happened to stop,
// not where the surface bends: two neighbouring charts often fit one normal cone together.
// Merging them gives fewer charts (fewer jumps for marching, less gutter) without more
// distortion than the cone allows.
#pragma once

#include "runtime/atlas/chart_segmentation.h"

namespace fgsg::rt::atlas {

// Merges neighbouring charts while the union still has a seed, a face of its own, whose
// normal is within `maxNormalDeviationDegrees` of every face's: the growing criterion,
// with the seed chosen afresh (the face closest to the union's mean normal). Pairs are
// tried most alike first (their mean normals), in rounds until none merges; charts are
// then numbered by their lowest face. Deterministic.
void mergeCompatibleCharts(const surface::SurfaceMesh& mesh, double maxNormalDeviationDegrees,
                           Segmentation& segmentation);

}  // namespace fgsg::rt::atlas
