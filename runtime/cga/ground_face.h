// CityEngine's initial shape (a lot in the `.cga` dialect): a face lying in its scope's XZ
// plane, y up (scope.sy = 0), x along the polygon's first edge, z across the ground. It is
// stored as a Polyhedron of that one face, so that split(x)/split(z), s(), t(), center(),
// i(), comp(f) and scope.s* act on it as in CityEngine; extrude, offset and the roofs,
// which take fgsg's polygon (Z its normal), get it through groundToPolygon.
#pragma once

#include "runtime/geometry.h"
#include "runtime/scope.h"

namespace fgsg::rt::cga {

// A one-face Polyhedron whose face lies in its scope's XZ plane.
bool isGroundFace(const GeomRef& geom, const GeometryArena& arena);

// fgsg's polygon (in its scope's XY plane, Z its normal) as a ground face: y the
// polygon's normal, x along `xAxis` when given (projected onto the face), else along its
// first edge; z = x × y. The scope's other state (colour, texture, place) is kept.
void polygonOnGround(Scope& scope, GeomRef& geom, GeometryArena& arena, const Vec3* xAxis = nullptr);

// CityEngine's object coordinate system of an initial shape given as fgsg's polygon (a
// lot before polygonOnGround): origin at the first corner of the outline's first edge,
// x along that edge, y the polygon's normal, z = x × y, as the P and axes of a Scope (S,
// the rest, unused). Other geometry, or none: the scope's own P and axes.
Scope initialShapeFrame(const Scope& scope, const GeomRef& geom, const GeometryArena& arena);

// A ground face as fgsg's polygon (solidFrameOnPolygon's inverse: x kept, z up).
void groundToPolygon(Scope& scope, GeomRef& geom, GeometryArena& arena);

}  // namespace fgsg::rt::cga
