// CityEngine's i() on a shape with trim planes: the inserted asset's mesh cut by them with
// everything it carries. trimGeometry (trim_planes.h) cuts positions only; a cut asset
// keeps its normals, its texture coordinates (set 0 and every uv set it has), and its
// images, so a textured cornice mitred at a corner still shows its texture.
#pragma once

#include "runtime/cga/trim_planes.h"
#include "runtime/mesh.h"

#include <vector>

namespace fgsg::rt::cga {

// `asset` (a library mesh in its unit box; `zUp` turns it as insertTransform does, (x, y,
// z) -> (x, z, 1 - y)) cut by `planes` (world) as it fills `scope`. Each of its triangles
// is clipped (Sutherland-Hodgman): a corner made on a cut edge interpolates the edge's
// normal and texture coordinates linearly. A closed asset's cuts are closed by a cap face
// per loop of cut edges (as trimGeometry closes a solid): a cap's corner keeps the texture
// coordinates the face it was cut from has there (the image continues over the cut), its
// normal is the cap's, its image that of the face whose cut edge starts the loop.
// The result is in the scope's normalised coordinates, a face's vertices its own (flat
// faces, as ownGeometryMesh), with the asset's images and texture runs; no triangles when
// the planes cut all of it away.
Mesh trimAssetMesh(const Scope& scope, const Mesh& asset, bool zUp, const std::vector<TrimPlane>& planes);

}  // namespace fgsg::rt::cga
