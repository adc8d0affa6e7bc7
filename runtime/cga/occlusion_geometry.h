// CityEngine's occlusion queries on real geometry (inside, overlaps, touches) and the
// scope distance of minimumDistance. A shape's geometry is a soup of world triangles;
// an occluder must be closed (CityEngine tests only closed surfaces). Points are
// classified against a closed soup by their distance to its surface (within the contact
// tolerance: on it) and their winding number (inside or outside), which needs no shared
// vertices, so split pieces with T-junctions stay closed.
#pragma once

#include "runtime/geometry.h"
#include "runtime/scope.h"

#include <array>
#include <vector>

namespace fgsg::rt::cga {

// Two surfaces closer than this (metres) touch; a point closer to a surface is on it.
// CityEngine does not document its tolerance; 0.1 mm is far above the rounding of splits
// (1e-12 relative) and far below anything a model means.
inline constexpr double kContactTolerance = 1e-4;

struct TriangleSoup {
  std::vector<std::array<Vec3, 3>> triangles;  // outward (counter-clockwise) when closed
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();   // world bounds
  bool closed = false;  // a solid: its triangles' vector areas add up to nothing
};

// The shape's own geometry (a box, a polygon, a solid) as world triangles; a closed one
// oriented outward. Edges and points give no triangles.
TriangleSoup shapeTriangles(const Scope& scope, const GeomRef& geom, const GeometryArena& arena);
TriangleSoup fromTriangles(std::vector<std::array<Vec3, 3>> triangles);

enum class Contact { Inside, Overlaps, Touches };

// Whether `query` (any geometry) lies inside the closed `occluder` (every point in it or on
// its surface), overlaps it (their interiors share a point deeper than the tolerance; for
// a flat query: part of it lies in the occluder's interior) or touches it (overlaps, or
// their surfaces come within the tolerance). False when the occluder is not closed.
bool contact(Contact test, const TriangleSoup& query, const TriangleSoup& occluder,
             double tolerance = kContactTolerance);

// The distance between two scope boxes (0 when they meet or one holds the other); a
// scope with a zero size is its rectangle.
double scopeDistance(const Scope& a, const Scope& b);

// Primitives, exposed for their tests.
double pointTriangleDistance(const Vec3& p, const std::array<Vec3, 3>& t);
double segmentDistance(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2);
double triangleDistance(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);
// The generalized winding number of p about a closed soup: 1 inside, 0 outside.
double windingNumber(const Vec3& p, const TriangleSoup& soup);

}  // namespace fgsg::rt::cga
