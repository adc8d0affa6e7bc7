// CityEngine's trim planes (attr_trim, op_trim): comp(f) gives each face a plane at every
// edge it shares with another face of the geometry it came from, the plane through that
// edge halfway between the two faces (the mitre of the corner); trim() keeps the part of
// a shape's geometry on the face's side of its planes. Horizontal and vertical planes are
// told apart by their edge: less than 40 degrees from the pivot's xz plane is horizontal.
#pragma once

#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"

#include <string>
#include <vector>

namespace fgsg::rt::cga {

// A plane in world coordinates: the kept side is where (p - point) . normal <= 0 (normal
// unit, pointing at what is cut off).
struct TrimPlane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitX();
  bool horizontal = false;
};

// The trim planes of each face (world points, unit outward normals): one per edge that
// exactly one other face walks too (its ends within `tol`), unless the two faces lie in one
// plane or fold back onto each other. `up`: the pivot's y axis (the classification's).
std::vector<std::vector<TrimPlane>> faceTrimPlanes(const std::vector<Polygon3>& faces,
                                                   const std::vector<Vec3>& normals, const Vec3& up, double tol);

// The trim planes comp(f) gives each of its parts (`parts`, what components() made of the
// shape `scope` / `geom`): a face part those of the face it is; other parts none.
std::vector<std::vector<TrimPlane>> compTrimPlanes(const Scope& scope, const GeomRef& geom,
                                                   const GeometryArena& arena, const std::vector<Part>& parts,
                                                   const Vec3& up);

// trim(): the geometry cut by `planes`, the scope kept. A solid's cuts are closed by cap
// faces (the cut edges chained into loops), a polygon is clipped, an edge stays as it is.
// Returns true when nothing was left (out.geom is then a polyhedron without faces); it
// cannot fail.
bool trimGeometry(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const std::vector<TrimPlane>& planes,
                  Part& out);

}  // namespace fgsg::rt::cga
