// CityEngine's geometry functions (geometry.area(), height(), nVertices(), nFaces(),
// isPlanar(tol), isConcave(), boundaryLength(), angle(maxSlope | azimuth | zenith),
// du / dv(0, uvSpace)) on a shape's own geometry: a box (its six
// faces; a flat box its one face), a polygon or a solid. World units (metres).
#pragma once

#include "runtime/cga/uv_projection.h"
#include "runtime/geometry.h"
#include "runtime/scope.h"

#include <array>
#include <vector>

namespace fgsg::rt::cga {

struct GeometryFacts {
  double area = 0;            // all faces (a solid's bottom too)
  double height = 0;          // the extent of its vertices along world Y
  int vertices = 0;           // distinct corners (a cube has 8)
  int faces = 0;
  bool concave = false;       // a face with a reflex corner or a hole
  double boundaryLength = 0;  // edges only one face has: a polygon's perimeter, 0 for a closed solid
};

GeometryFacts geometryFacts(const Scope& scope, const GeomRef& geom, const GeometryArena& arena);

// Whether every face lies in one plane: face normals within `toleranceDegrees` of the
// first's and every corner on its plane (within the same angle seen over the geometry's
// size). No faces (an edge): false.
bool geometryIsPlanar(const Scope& scope, const GeomRef& geom, const GeometryArena& arena, double toleranceDegrees);

// geometry.angle's selectors, in the order fgsg's IR numbers them.
enum class GeometryAngleKind { MaxSlope = 0, Azimuth = 1, Zenith = 2 };

// geometry.angle(kind) in degrees, from the faces' world normals (faces without area
// ignored). A face's slope is the angle between its plane and the world's xz plane, 0 to
// 90 whichever way it looks. MaxSlope: the steepest face's; Zenith: 90 - MaxSlope;
// Azimuth: the direction the steepest face (the first of equals) looks, its normal laid
// on the xz plane, clockwise from north (-z): east (+x) 90, south 180, west 270, in
// [0, 360); 0 where that face is level. No faces (an edge): 0 for MaxSlope and Azimuth,
// 90 for Zenith.
double geometryAngle(const Scope& scope, const GeomRef& geom, const GeometryArena& arena, GeometryAngleKind kind);

// geometry.du(0, uvSpace) and dv: how far the texture coordinates that `projection` gives
// the geometry (every face's corners, each face projected as projectTexcoords projects it)
// spread along u and along v: {max u - min u, max v - min v}. No faces: {0, 0}.
std::array<double, 2> geometryUvSpread(const Scope& scope, const GeomRef& geom, const GeometryArena& arena,
                                       const UvProjection& projection);

// Every face of the geometry in world space, as the queries above measure it (a box's six,
// a flat box's one, a polygon's one, a solid's all; an edge none), each counter-clockwise
// about its outward normal. insertAlongUV lays its asset on them.
std::vector<std::vector<Vec3>> geometryWorldFaces(const Scope& scope, const GeomRef& geom, const GeometryArena& arena);

}  // namespace fgsg::rt::cga
