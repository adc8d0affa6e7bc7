// Exact clipping of convex polygons in a face's parameter plane, for clipped cells
// (docs/cells.md "Clipped and mitred cells"): a cell that would cross the face's outline
// or a claim is the part of its rectangle in free space, and free space (the face's
// triangles minus convex claims) is a set of convex pieces. Every operation here keeps
// convexity, so claims stay convex and the occupancy map stays exact.
// Polygons are counter-clockwise, corners not repeated.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace fgsg::rt::cells {

using Vec2 = Eigen::Vector2d;
using Polygon2 = std::vector<Vec2>;
// A convex solid as its faces: convex polygons in space, counter-clockwise seen from
// outside (a mitred cell, cell.h).
using SolidFaces = std::vector<std::vector<Eigen::Vector3d>>;

// Positive for a counter-clockwise polygon (the shoelace formula).
double signedArea(const Polygon2& p);
// The part of convex `p` with n . x <= c (Sutherland–Hodgman against one line).
Polygon2 clipHalfPlane(const Polygon2& p, const Vec2& n, double c);
// The same, written into `out` (cleared first; not `p`), so hot loops reuse its storage.
void clipHalfPlaneInto(const Polygon2& p, const Vec2& n, double c, Polygon2& out);
// The intersection of two convex polygons (`clip` counter-clockwise).
Polygon2 intersectConvex(const Polygon2& p, const Polygon2& clip);
// Convex `p` minus convex `hole`: disjoint convex pieces, those of area <= minArea dropped.
// Each piece lies outside one edge of the hole and inside the edges before it.
std::vector<Polygon2> subtractConvex(const Polygon2& p, const Polygon2& hole, double minArea);
// Whether `hole` leaves `p` whole in subtractConvex: at the first side of the hole that
// `p` does not lie wholly inside, it lies wholly outside (touching the side allowed).
// Then subtractConvex gives `p` itself where `p` has no repeated corners (a clip's
// output) and more than minArea, without allocating.
bool holeMisses(const Polygon2& p, const Polygon2& hole);
// The union of convex pieces with disjoint interiors when that union is convex itself
// (their convex hull's area is their summed area within `areaTol`); empty otherwise.
Polygon2 convexUnion(const std::vector<Polygon2>& pieces, double areaTol);
// Convex `p` with every side moved `by` inwards (the intersection of the moved
// half-planes, so sides that vanish are handled); empty when nothing is left.
Polygon2 insetConvex(const Polygon2& p, double by);
// The part of convex solid `s` with n . x <= c (n unit): each face clipped, and the cut
// closed by a new face on the plane; empty when nothing is left. `tol`: a distance below
// which a corner counts as on the plane.
SolidFaces clipSolid(const SolidFaces& s, const Eigen::Vector3d& n, double c, double tol);

}  // namespace fgsg::rt::cells
