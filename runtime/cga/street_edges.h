// CityEngine's street.front / back / left / right / side from a lot's street widths (the
// lot's "streetWidth": one value per edge, 0 where no street runs along it). Without them
// the selectors fall back to the object system (setback.cpp, components.cpp).
//
// street.front: a lot edge with a street width above 0; a component that lies on no lot
// edge (a setback remainder's edge, a mass's wall, a corner) when its level outward
// direction is within 45 degrees of such an edge's outward direction (the diagonal counts).
// The others are classed in the main street's frame, the street edge of the greatest width
// (the first of the ring's edges on a tie, as CityEngine's first edge): street.back when
// the direction is within 45 degrees of facing away from it (the diagonal counts), else
// street.right or street.left by the side it faces, seen from that street looking at the
// lot; facing the main street squarely without being on a street: none of them. A lot
// whose widths are all 0 (an inner lot) has no street.front and is classed in the object
// system's frame (its front the lot's first edge). An edge on a hole's ring (a courtyard)
// is on no street whichever way it faces: street.back, .left or .right by its direction
// (or none, facing the main street squarely), never street.front.
#pragma once

#include "runtime/scope.h"

#include <vector>

namespace fgsg::rt::cga {

enum StreetSide : unsigned { kStreetFront = 1, kStreetBack = 2, kStreetLeft = 4, kStreetRight = 8 };

struct StreetEdges {
  struct Edge {
    Vec3 a, b;      // on the ground (y up), the lot's ring counter-clockwise seen from above
    Vec3 outward;   // level, unit
    double width = 0.0;
  };
  std::vector<Edge> edges;
  std::vector<Edge> holeEdges;  // the holes' rings (a, b only): never on a street
  Vec3 front = Vec3::UnitZ(), right = Vec3::UnitX();  // the main street's frame, level
  double tol = 1e-9;                                   // a point this near an edge lies on it
};

// The lot's outer ring (world points, y up, counter-clockwise seen from above) and its
// street widths (edge i from ring[i] to ring[i + 1]); `objectFront`: the object system's
// front (its z), the frame of a lot without a street; `holes` its inner rings.
StreetEdges streetEdgesOfLot(const std::vector<Vec3>& ring, const std::vector<double>& width, const Vec3& objectFront,
                             const std::vector<std::vector<Vec3>>& holes = {});

// The StreetSide of a component whose outward direction is `direction` (its level part
// counts; none when it has none); `a` and `b` the ends of an edge component (else null),
// which decide by the lot edge they lie on.
unsigned streetSide(const StreetEdges& streets, const Vec3& direction, const Vec3* a = nullptr, const Vec3* b = nullptr);

}  // namespace fgsg::rt::cga
