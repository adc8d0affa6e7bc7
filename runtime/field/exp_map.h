// Geodesic polar coordinates by propagation, without a linear solve: the discrete
// exponential map (Schmidt, Grimm, Wyvill 2006, "Interactive decal compositing with
// discrete exponential maps"). Vertices are visited in order of distance from the source
// (Dijkstra on the estimates); each takes the average, over its already visited
// neighbours p, of U(p) + A(p) e(p, q): U the point's polar coordinates as a plane vector
// in the source's tangent plane (reference direction = +x), e the edge to q in p's
// tangent plane (its length kept), A(p) the rotation of p's frame onto the source's,
// itself carried from neighbour to neighbour by the vertex-to-vertex transports. Then
// rho = |U|, theta = arg U, and the reference seen at q is A(q)'s inverse.
//
// Exact on a flat mesh; on curved ones it develops the surface along the propagation
// front, which is accurate near the source and drifts with distance (the price of
// needing no factorisation: O(n log n) per source, and nothing at all beyond
// `maxDistance`). HeatGeodesics is the accurate alternative.
#pragma once

#include "runtime/field/geodesics.h"

#include <cmath>

namespace fgsg::rt::field {

// Vertices farther than maxDistance are not visited: distance +infinity, angle and
// reference 1.
PolarMap exponentialMap(const TangentFrames& frames, const SurfacePoint& source,
                        const Vec3& reference, double maxDistance = INFINITY);

}  // namespace fgsg::rt::field
