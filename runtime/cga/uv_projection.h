// CGA's texture projection (setupProjection + projectUV): `Texture("brick.png", 2, 1.5)`
// fixes a frame — the scope it runs in — and every leaf derived from that scope gets
// texture coordinates measured in that frame, so the bricks run on unbroken across the
// split pieces of a facade. A face is projected onto the frame's plane it faces most
// (XY, YZ or XZ): a facade onto XY as CGA does, the reveal of an inset window or the top
// of a wall onto a plane it is not edge-on to, instead of a smear.
#pragma once

#include "runtime/mesh.h"
#include "runtime/scope.h"

#include <array>
#include <cstdint>

namespace fgsg::rt::cga {

// CGA's setupProjection / tileUV / scaleUV ... (ir::UvOp) act on a projection too: each
// makes a new one from the scope's, which the shapes derived from it inherit.
struct UvProjection {
  Vec3 origin = Vec3::Zero();    // u = v = 0 here
  Mat3 axes = Mat3::Identity();  // the frame's X (u), Y (v) and Z, in world space
  double tileWidth = 1, tileHeight = 1;  // metres per repeat of the image along X and Y (< 0: mirrored)
  uint32_t texture = 0;          // InstanceList::textures index; kNoImage: coordinates without an image yet
  // CGA's setupProjection: every face projected onto the frame's XY plane (faces across it
  // smeared, as CityEngine does), not onto the plane each face looks along most.
  bool planar = false;
  // The uv operations after the projection (scaleUV, translateUV, rotateUV, normalizeUV):
  // (u, v) -> (a u + b v + c, d u + e v + f), as {a, b, c, d, e, f}.
  std::array<double, 6> uvTransform{1, 0, 0, 0, 1, 0};
  // CGA's deleteUV(0): false, the faces carry no texture coordinates (nor draw the image)
  // until projectUV(0) projects them again from the setup; the uv operations do nothing.
  bool coordinates = true;
  // The projection as its setupProjection or texture made it (1 + its index), which
  // projectUV(0) after deleteUV(0) projects again: later uv operations were on the
  // coordinates deleteUV removed. 0: this one is that setup.
  uint32_t setup = 0;
  static constexpr uint32_t kNoImage = UINT32_MAX;
  bool hasImage() const { return texture != kNoImage; }
  // Whether the leaves below it get texture coordinates and its image.
  bool draws() const { return hasImage() && coordinates; }
};

// The projection `Texture` sets up in `scope`: its frame, and the tile sizes given (or,
// when both are 0, the scope's X and Y sizes: one image over the scope; a size of 0 reads 1).
UvProjection projectionAt(const Scope& scope, double tileWidth, double tileHeight, uint32_t texture);

// Fills the texture coordinates of `mesh`, a leaf's geometry in `scope`'s unit box with
// one normal per vertex (flat faces, own vertices: rt::cga::ownGeometryMesh): each vertex
// is projected onto the frame plane its face looks along most, turned so the image reads
// the right way round from the face's front.
void projectTexcoords(Mesh& mesh, const Scope& scope, const UvProjection& projection);
// The same coordinates into `into` (another uv set than set 0's Mesh::texcoords).
void projectTexcoordsInto(const Mesh& mesh, const Scope& scope, const UvProjection& projection,
                          MeshArray<float>& into);

// The (u, v) of the world point `world` on a face whose normal (world space) is `facing`
// under `projection`, its uv transform applied: what projectTexcoords gives a vertex.
std::array<double, 2> projectPoint(const UvProjection& projection, const Vec3& world, const Vec3& facing);

// The projection's (u, v) range over the corners of `scope`'s box, each projected onto the
// frame's XY plane (the uv transform applied): {uMin, uMax, vMin, vMax}. normalizeUV and
// tileUV measure a shape by it.
std::array<double, 4> uvRangeOfScope(const UvProjection& projection, const Scope& scope);

}  // namespace fgsg::rt::cga
