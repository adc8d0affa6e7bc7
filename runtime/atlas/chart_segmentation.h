// The first cut of the surface into charts (Sander et al.'s multi-chart geometry images,
// which Buron et al. §4 build on): regions grown over shared edges while the faces stay
// nearly flat relative to where the region started. Whether each region can be laid flat
// in one piece is decided afterwards (chart_splitting.h).
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <vector>

namespace fgsg::rt::atlas {

struct Segmentation {
  int chartCount = 0;
  std::vector<int> faceChart;  // per face
};

// Per face: its centroid, the point distances between neighbouring faces are measured at.
std::vector<Vec3> faceCentroids(const surface::SurfaceMesh& mesh);

// Grows one chart at a time from a seed face, nearest faces first (distance between face
// centroids across shared edges, so charts come out round rather than ragged). A face
// joins while its normal is within `maxNormalDeviationDegrees` of the seed's. The next
// seed is the first face a finished chart turned away, so charts tile the surface from
// one side to the other instead of leaving scattered left-overs; a new connected component
// starts at its lowest-numbered face. Deterministic; needs the mesh's topology.
Segmentation growCharts(const surface::SurfaceMesh& mesh, const std::vector<Vec3>& centroids,
                        double maxNormalDeviationDegrees);

}  // namespace fgsg::rt::atlas
