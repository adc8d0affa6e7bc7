// CityEngine's insertAlongUV(uvSet, asset, height[, heightDirection, heightAlignment])
// (op_insertAlongUV): an asset laid out in the uv space of one of the shape's uv sets, cut
// where the shape's uvs end and bent onto its faces: the result is new geometry (a baked
// mesh), not an instance.
//
// The asset's box (normalised to the unit cube, as AssetLibrary keeps assets) is mapped as
// the reference says: its x onto u in [0, 1], repeated for every whole u the shape's uvs
// reach; its z onto -v (z's minimum at v = 1, its maximum at v = 0), once; its y onto the
// height, 0 at the shape's surface and `height` at the asset's top (alignPosition), or
// scaled by the same factor about the asset file's own y = 0 (keepPosition). Each asset
// point (u, v, h) lands at the shape's surface point with those uvs plus h along the scope's
// y axis or, with vertexNormals, along the shape's vertex normals interpolated over the face.
// Choices where the reference is silent are in docs/cga.md ("insertAlongUV").
#pragma once

#include "runtime/cga/cga.h"
#include "runtime/cga/uv_projection.h"
#include "runtime/deadline.h"
#include "runtime/mesh.h"

#include <array>
#include <string>
#include <vector>

namespace fgsg::rt::cga {

// One face of the shape in world space with the (u, v) of each corner.
struct AlongUvFace {
  std::vector<Vec3> corners;
  std::vector<std::array<double, 2>> uvs;
};

struct AlongUvOptions {
  double height = 0.0;         // metres, may be 0 (a flat asset) or negative (hanging below)
  bool vertexNormals = false;  // heightDirection vertex.normal (else scope.y)
  bool keepPosition = false;   // heightAlignment keepPosition (else alignPosition)
  Vec3 up = Vec3::UnitY();     // scope.y: the shape's scope y axis (world)
  // At most this many output faces (the shape's u range times the asset's triangles):
  // more is an error, not an endless loop on a shape whose uvs run to 1e9.
  size_t maxFaces = 4'000'000;
  // --max-seconds, asked for every piece of the asset cut by a cell and every pair of
  // cells compared (throwing TimeLimitReached): a shape of many faces times millions of
  // asset triangles could otherwise run far past the limit. None: no limit.
  Deadline* deadline = nullptr;
};

// The asset `asset` (unit-cube positions; `sourceBox` its file's box before normalising:
// lo x y z, hi x y z) laid along `faces`' uvs. `out` gets the world faces (convex
// polygons, triangles with vertexNormals), each turned to face away from the surface on
// its top, as the asset's faces face out of it. False and a message when the uvs of two
// faces overlap (the asset would be inserted twice there), when nothing of the asset lands
// on the shape, or when the output would exceed maxFaces.
bool insertAlongUvFaces(const std::vector<AlongUvFace>& faces, const Mesh& asset,
                        const std::array<double, 6>& sourceBox, const AlongUvOptions& options,
                        std::vector<std::vector<Vec3>>& out, std::string& error);

// The shape's own faces (a box's six, a flat box's or polygon's one, a solid's) with the
// uvs `projection` gives their corners (each face projected as its leaves' texture
// coordinates are), the asset laid along them, and the result as a Part: a solid of those
// faces in a scope with the shape's axes, fitted around it. An edge has no faces: false.
bool insertAlongUv(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const UvProjection& projection,
                   const Mesh& asset, const std::array<double, 6>& sourceBox, const AlongUvOptions& options,
                   Part& out, std::string& error);

}  // namespace fgsg::rt::cga
