// The inverse poly-cube map of Chan & Hui 2013 §5.1 (after Tarini et al. 2004,
// PolyCube-Maps, the paper's [14]): a polycube approximating a surface, whose boundary is
// made of unit squares, the "face-lets"; a 2D pattern laid on every face-let in [0,1]^2 is
// carried onto the surface by casting a ray from each face-let point to the surface.
//
//   PolycubeMap pc(mesh, {.resolution = 16});
//   for (size_t f = 0; f < pc.facelets().size(); ++f) {
//     MappedPoint p = pc.map(f, 0.25, 0.5);   // face-let point (a, b) -> surface point
//     ... p.position, p.normal, p.tangentU, p.tangentV, p.face, p.bary ...
//   }
//
// Texture space (§5.1.3). The paper gives every mesh vertex a 3D texture coordinate in
// which the polycube's cells are unit cubes. Ours is the vertex position in cell units:
// t = (x - gridOrigin) / cellSize, so lattice vertices (cell corners) are the integer
// points and texture space is world space uniformly scaled (directions are the same in
// both; only lengths scale).
//
// The polycube (our rule; the paper takes Tarini's hand-made polycubes). A regular grid
// aligned with the mesh's bounding box (its minimum corner is a lattice point), `resolution`
// cells along the largest extent, padded by two empty cells on every side. A cell is solid
//   1. when the surface touches it (exact triangle-box overlap test on the closed cell,
//      enlarged by 1e-4 cell) and its centre is inside: on the inner side of the nearest
//      surface point, judged by the angle-weighted pseudo-normal of the face, edge or
//      vertex that point lies on (exact for a closed mesh; for a mesh with boundary this
//      is the nearest face's side), or
//   2. when the surface does not touch it and it is enclosed: an outside flood fill
//      (6-connected, from the padding, through untouched cells) does not reach it. A
//      watertight surface separates its inside from the padding; an open one (a plane, a
//      cylinder without caps) lets the fill in, and its solid is the layer of touched cells
//      behind the sheet.
//   (When that leaves no solid cell at all, e.g. a surface thinner than a cell everywhere,
//   every touched or enclosed cell is solid instead.)
//   3. Regularised: at a lattice vertex where the direction d(v) below does not point into
//      the solid through every face-let meeting there (a non-manifold vertex or edge, e.g.
//      two cells sharing only an edge, or a cell under an overhang), the smallest box of the
//      vertex's eight cells holding all its solid cells is filled; repeated until no such
//      vertex is left. This only adds cells inside the solid's bounding box (a box is
//      regular everywhere), so it ends.
// So the polycube hugs the surface: for a closed mesh every solid cell's centre is inside
// and the surface crosses the face-lets' neighbourhood within about a cell. Parts thinner
// than a cell may hold no cell centre and then have no face-lets of their own (they are
// reached only by rays passing them). Face-lets are the cell faces between a solid cell and
// an empty one, each with its outward normal.
//
// Projection (§5.1.4, Table 1). Every lattice vertex v on the polycube gets the direction
//   d(v) = componentwise sign of sum over the solid cells c around v of (centre(c) - v),
// a vector in {-1,0,1}^3 pointing from v into the solid: (0,0,-1) on a flat top,
// (-1,0,-1) on a convex edge along y, (-1,-1,-1) at a convex corner, and the same signs at
// concave edges and corners (into the solid, towards the edge or corner). A face-let point
// (a, b) projects along the bilinear blend of its four corners' directions (not
// normalised):
//   D(a,b) = (1-a)(1-b) d(c00) + a(1-b) d(c10) + (1-a)b d(c01) + ab d(c11).
// How this relates to Table 1. Tarini's dual cubes are centred at the lattice vertices,
// so each covers a quarter of every face-let meeting at its vertex, and Table 1 gives the
// direction inside one dual cube by its type: 3 (convex corner) (-r,-s,-t), radial towards
// the solid cell's centre; 4a (convex edge) (-r,0,-t), radial about an axis; 4b (flat)
// (0,0,-1), along the inward normal; 5a-5c (concave) piecewise formulas (5a divides by s
// or r). At the lattice vertex itself these are (up to length) our d(v): (-1,-1,-1),
// (-1,0,-1), (0,0,-1). We keep those vertex directions but blend them bilinearly over the
// whole face-let instead of piecewise over its quarters, and use the same rule for the
// concave types: one formula for every configuration (including those Tarini's six types
// do not list), continuous everywhere, and never zero (below). The difference: near a
// convex feature the paper's direction is the pure normal at the face-let's centre and
// ours leans towards the feature already there. Like Table 1's, our directions run from
// the polycube to the surface (Tarini's reversed).
// Seamless by construction: on a face-let's edge the direction depends only on the edge's
// two end vertices, and at a lattice vertex only on the vertex, so two face-lets sharing an
// edge or a vertex cast the same ray from a shared point and map it to the same surface
// point. Regularisation makes d(v) . normal < 0 for every face-let at v, so D(a,b) always
// points into the solid.
//
// The surface point is found on the LINE through the face-let point along D (texture
// space): the hit nearest the point, forwards or backwards (the surface may lie on either
// side of a face-let, since the polycube crosses it), with Embree 3 in robust mode; the hit
// is then recomputed in double precision on the hit triangle, walking to the neighbouring
// triangle when the float hit was across an edge. Fallback: when the line meets nothing
// (it can pass beside a part thinner than a cell or a strongly curved one near a polycube
// corner, and always does beyond the border of an open surface), the surface point nearest
// the face-let point is taken instead (through Embree's point query) and `hit` is false;
// fallbackCount() counts these. Both are functions of the face-let point alone, so the
// fallback keeps the map seamless.
//
// The result (§5.1.4's last step): face and barycentric coordinates, the position, the
// smooth normal (vertex normals interpolated, unit) and tangents: tangentU / tangentV are
// the face-let's u and v directions projected onto the tangent plane (orthogonal to the
// normal) and normalised; they are orthogonal to the normal but not in general to each
// other. Where u (or v) is parallel to the normal the other tangent crossed with the
// normal stands in, keeping (tangentU, tangentV, normal) right-handed.
//
// Deterministic (face-lets in cell order z, y, x, then axis x y z, then side - +);
// map() is const and thread-safe.
#pragma once

#include "runtime/scope.h"
#include "runtime/surface/surface_mesh.h"

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace fgsg::rt::evolve {

constexpr int kMaxPolycubeResolution = 256;  // cells along the largest extent

struct PolycubeOptions {
  // The cell's edge length in world units; 0: the largest bounding-box extent / resolution.
  double cellSize = 0;
  // Cells along the largest extent when cellSize is 0 (1..kMaxPolycubeResolution).
  int resolution = 8;
  // A polycube with more face-lets than this is refused (memory: ~150 bytes each).
  size_t maxFacelets = 1'000'000;
};

// One face of the polycube: a unit square in cell units with its outward normal.
struct Facelet {
  std::array<int, 3> cell;  // the solid cell it bounds (grid indices)
  int axis;                 // the normal's axis: 0 x, 1 y, 2 z
  int sign;                 // +1 or -1: which side of the cell
  // World space: the face-let point (a, b), a and b in [0,1], is origin + a u + b v; u and
  // v have the cell size as length and run along the positive axes, u x v along normal
  // (counter-clockwise seen from outside): for sign +1, u along axis + 1 and v along
  // axis + 2 (mod 3); for sign -1 the other way round. normal is unit.
  Vec3 origin, u, v, normal;

  Vec3 point(double a, double b) const { return origin + a * u + b * v; }
};

// A face-let point carried onto the surface.
struct MappedPoint {
  bool hit = false;  // false: the line met nothing and this is the nearest surface point
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::Zero();    // smooth, unit
  Vec3 tangentU = Vec3::Zero();  // unit, orthogonal to normal
  Vec3 tangentV = Vec3::Zero();  // unit, orthogonal to normal
  int face = -1;
  Vec3 bary = Vec3::Zero();      // with respect to the face's corners, sum 1, all >= 0
};

class PolycubeMap {
 public:
  // Builds the polycube around `mesh` (its topology built; a copy is kept). Throws
  // std::invalid_argument for an empty mesh or one without topology, a mesh of no extent,
  // a resolution outside 1..kMaxPolycubeResolution, a cell size that is negative, not
  // finite or makes more than kMaxPolycubeResolution cells along the largest extent, or a
  // polycube with more than maxFacelets face-lets.
  explicit PolycubeMap(const surface::SurfaceMesh& mesh, const PolycubeOptions& options = {});
  ~PolycubeMap();
  PolycubeMap(PolycubeMap&&) noexcept;
  PolycubeMap& operator=(PolycubeMap&&) noexcept;
  PolycubeMap(const PolycubeMap&) = delete;
  PolycubeMap& operator=(const PolycubeMap&) = delete;

  const std::vector<Facelet>& facelets() const;
  double cellSize() const;
  Vec3 gridOrigin() const;              // world position of lattice point (0,0,0)
  std::array<int, 3> gridCells() const;  // cells along x, y, z (padding included)
  size_t solidCells() const;

  // The unit projection direction at face-let point (a, b) (world and texture space alike).
  Vec3 projectionDirection(size_t facelet, double a, double b) const;
  // The surface point face-let point (a, b) maps to. Throws std::out_of_range for a bad
  // face-let index or a, b outside [0,1].
  MappedPoint map(size_t facelet, double a, double b) const;
  // How many map() calls so far fell back to the nearest surface point.
  size_t fallbackCount() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fgsg::rt::evolve
