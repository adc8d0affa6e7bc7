// Laying one chart flat with least-squares conformal maps (Lévy et al. 2002), the
// parametrization Sander et al.'s charts and Buron et al. §4 start from: angles are kept
// as well as a flat layout allows, the boundary is free.
//
// Our own Eigen solve rather than CGAL's Surface_mesh_parameterization: a chart is
// already an indexed mesh here, and CGAL would need a CGAL::Surface_mesh rebuilt per
// chart, its border halfedge and its solver traits, for the same sparse system. The
// energy is written as Dirichlet energy minus the signed area of the flat boundary
// (Mullen et al. 2008, equal to LSCM's), so the symmetric system is solved by a sparse
// Cholesky factorization and the minimum prefers the orientation that is not mirrored.
#pragma once

#include "runtime/atlas/atlas.h"
#include "runtime/atlas/chart_mesh.h"

#include <vector>

namespace fgsg::rt::atlas {

// A flat position per chart vertex (two boundary vertices far apart are pinned, so the
// layout has about the surface's own size). `chart` must be a disk. False when the
// system cannot be solved or the solution is not finite; folds are not checked here.
bool parametrizeConformal(const surface::SurfaceMesh& mesh, const ChartMesh& chart,
                          std::vector<Vec2>& uv);

}  // namespace fgsg::rt::atlas
