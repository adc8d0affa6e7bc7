// Isotropic remeshing (Botsch & Kobbelt 2004) of a closed triangle mesh onto a surface
// known by its closest-point projection: long edges split, short ones collapsed, edges
// flipped towards valence 6, vertices relaxed in their tangent planes and projected back.
// Everything runs in index order on OpenMesh's arrays, so the same input gives the same
// mesh in every run (CGAL's remesher depends on where its elements lie in memory).
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <functional>

namespace fgsg::rt::surface {

// The point of the target surface closest to a point (near the surface).
using SurfaceProjection = std::function<Vec3(const Vec3&)>;

// Remeshes `mesh` (closed, manifold) towards edges of length `target`, `iterations`
// rounds; returns the new mesh with its topology built.
SurfaceMesh remeshIsotropic(const SurfaceMesh& mesh, double target, const SurfaceProjection& project,
                            int iterations = 5);

}  // namespace fgsg::rt::surface
