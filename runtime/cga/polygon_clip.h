// Planar polygons and polyhedra as plain values, in normalised scope coordinates (the
// scope box is the unit cube), for the CGA kernels: copied out of the arena, clipped to an
// axis-aligned slab, re-normalised to the slab's sub-box and stored back.
//
// Clipping a polyhedron closes the cut with a cap face only when the solid is convex: the
// cap of a convex solid is the convex hull of the cut points. Concave solids (a prism on an
// L-shaped footprint) are clipped without caps, so their parts are open where they were cut.
// A concave polygon that a slab cuts into several pieces comes back as one polygon whose
// pieces are joined by zero-width bridges along the cut (Sutherland-Hodgman): its area is
// exact and triangulate() accepts it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "runtime/geometry.h"
#include "runtime/scope.h"

namespace fgsg::rt::cga {

using Polygon3 = std::vector<Vec3>;

// Tolerances in normalised coordinates.
inline constexpr double kPlaneTol = 1e-9;  // a point this close to a cutting plane lies on it
inline constexpr double kMinArea = 1e-12;  // clipped faces with less area are dropped

// A Polygon (exactly one face) or a Polyhedron copied out of the arena.
struct LocalGeometry {
  GeomKind kind = GeomKind::Polygon;
  std::vector<Polygon3> faces;
  bool convex = false;  // polyhedra: cuts are closed by cap faces
};

LocalGeometry loadGeometry(const GeometryArena& arena, const GeomRef& ref);
GeomRef storeGeometry(GeometryArena& arena, const LocalGeometry& g);

// True when every slab of the scope box carries the same normalised geometry as the whole
// box: Box, Edge and the unit-square polygon (a box face). Subdiv and Repeat then hand
// the parent's GeomRef to every part: no clipping, no arena use.
bool isSlabInvariant(const GeometryArena& arena, const GeomRef& ref);
// The polygon (0,0) (1,0) (1,1) (0,1), counter-clockwise, starting at any corner.
bool isUnitSquare(const Vec3* pts, std::size_t count);

// Keeps the part of g with lo <= c[axis] <= hi. Returns false when nothing with area is
// left (g is then unspecified).
bool clipToSlab(LocalGeometry& g, int axis, double lo, double hi);

// Maps [lo, hi] on `axis` onto [0, 1]; a zero-length slab maps to 0 (a dimension of size
// zero keeps coordinate 0).
void renormalise(LocalGeometry& g, int axis, double lo, double hi);

// Newell's normal of a planar polygon: its length is twice the polygon's area.
Vec3 newellNormal(const Vec3* pts, std::size_t count);
inline Vec3 newellNormal(const Polygon3& p) { return newellNormal(p.data(), p.size()); }

// Whether each edge (pts[i] to pts[i + 1]) is a zero-width bridge joining a hole to its
// outline: an edge the polygon also runs along the other way. Points are compared
// exactly: a bridge's ends are the same points both ways.
std::vector<bool> bridgeEdges(const Polygon3& pts);

// A polygon's rings with its bridges taken out, each in the polygon's direction: the
// ring of the largest area first (the outline), then the holes. A polygon without
// bridges is its one ring.
std::vector<Polygon3> ringsOf(const Polygon3& pts);

// Ear clipping of a planar polygon, counter-clockwise about its Newell normal; concave
// polygons (L-shaped footprints) and the zero-width bridges of clipped concave polygons
// are accepted. Appends index triples into `pts`, each counter-clockwise like the polygon.
void earClip(const Vec3* pts, std::size_t count, std::vector<uint32_t>& tris);
inline void earClip(const Polygon3& pts, std::vector<uint32_t>& tris) { earClip(pts.data(), pts.size(), tris); }

// The scope box as a solid: faces front (+Z), right (+X), back (-Z), left (-X), top (+Y),
// bottom (-Y), each counter-clockwise seen from outside starting at its lower-left corner,
// so the side faces walk around a building.
const std::vector<Polygon3>& unitBoxFaces();

// The frame of a solid standing on a polygon: X kept, Y = the polygon's normal (up),
// Z = X x Y. The solid's XZ rectangle is the polygon scope's XY rectangle; a polygon
// point (x, y) lies at normalised (x, 0, 1 - y) of the new frame.
Scope solidFrameOnPolygon(const Scope& polygonScope);

}  // namespace fgsg::rt::cga
