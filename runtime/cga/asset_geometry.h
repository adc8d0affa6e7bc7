// What a shape's geometry is after CityEngine's i(): the inserted asset's mesh (the
// geometry.* queries, and every operation after the insert, read it).
#pragma once

#include "runtime/cga/polygon_clip.h"
#include "runtime/mesh.h"

namespace fgsg::rt::cga {

// `asset` (a library mesh in its unit box; `zUp` turned as insertTransform turns it) as a
// solid in the normalised coordinates of the scope it fills. The library keeps triangles
// only, so a face is each set of neighbouring triangles (sharing an edge, corners compared
// exactly) that lie in one plane, when their outline is one loop: a file's quad or n-gon,
// the built-in cube's six sides; a set whose outline is not one loop (a ring around a
// hole) stays triangles. Triangles without area are left out.
LocalGeometry assetGeometry(const Mesh& asset, bool zUp);

}  // namespace fgsg::rt::cga
