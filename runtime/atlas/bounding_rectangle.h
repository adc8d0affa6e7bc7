// The smallest rectangle around a chart, in any orientation: a generated chart's
// orientation in the plane is arbitrary, and turning it to that rectangle before packing
// wastes less of the geometry image.
#pragma once

#include "runtime/atlas/atlas.h"

#include <vector>

namespace fgsg::rt::atlas {

// The angle (radians) to turn `points` by, counter-clockwise, so that their smallest-area
// enclosing rectangle is aligned with the axes (a side of the smallest rectangle lies
// along an edge of the convex hull). 0 for fewer than three points. Deterministic.
double minimalRectangleAngle(const std::vector<Vec2>& points);

// The convex hull, counter-clockwise, without collinear points (Andrew's monotone chain).
std::vector<Vec2> convexHull(std::vector<Vec2> points);

}  // namespace fgsg::rt::atlas
