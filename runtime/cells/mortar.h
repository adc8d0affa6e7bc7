// Mortar (Legakis et al. 2001, §5): cells are shrunk to leave joints, and the joints are
// filled by the base mesh itself, grown outward so that it shows between the cells
// `recess` below their faces.
#pragma once

#include "runtime/mesh.h"
#include "runtime/surface/surface_mesh.h"

namespace fgsg::rt::cells {

// The base mesh with every vertex moved so that each face around it lies `offset`
// further out along its normal (least squares where more than three planes meet;
// flat faces stay flat, corners stay sharp), flat-shaded per face so that edges stay
// crisp. The mesh's topology must be built.
Mesh mortarMesh(const surface::SurfaceMesh& mesh, double offset);

}  // namespace fgsg::rt::cells
