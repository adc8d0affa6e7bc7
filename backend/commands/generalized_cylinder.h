// lpfg's and L-Py's generalized cylinders (`@Gs`, `@Gc`, `@Ge`; cpfg tutorial ch. 4): a
// circle swept along a smooth curve through the turtle's control points. Between two
// control points the curve is a cubic Hermite piece whose end tangents are the turtle's
// headings there, each as long as the distance between the points times 1.2 (cpfg's
// default tangent coefficient), so the curve scales without changing its shape. The rings
// stand across the curve and turn with it by parallel transport (the least rotation from
// one tangent to the next: no twist), starting from the turtle's frame at the first point.
#pragma once

#include "runtime/scope.h"

#include <cstdint>
#include <vector>

namespace fgsg::backend {

// One control point: where the turtle stood, its heading (unit), the radius there, and
// how many strips (rings after the first) the piece from the previous point gets.
struct CylinderControlPoint {
  rt::Vec3 position;
  rt::Vec3 heading;
  double radius = 0;
  uint32_t strips = 1;
};

// The swept tube: `rings` rings of `sides` vertices each (ring-major), the curve's point
// and unit tangent at each ring, and triangles facing out (counter-clockwise seen from
// outside). Open at both ends, as a swept surface.
struct CylinderSweep {
  std::vector<rt::Vec3> vertices;
  std::vector<uint32_t> triangles;
  std::vector<rt::Vec3> centres, tangents;
  size_t rings = 0;
};

// The tube through `points` (at least two) with a circle of `sides` sides; `up` (across
// the first heading) is where the first ring's vertex 0 lies, the others following
// counter-clockwise about the tangent. A piece whose two points coincide (closer than
// 1e-12 of the curve's size) adds no ring; a tube with no piece left has no vertices.
CylinderSweep sweepGeneralizedCylinder(const std::vector<CylinderControlPoint>& points, const rt::Vec3& up,
                                       int sides);

// cpfg's default tangent coefficient: each end tangent of a piece is this times its chord.
inline constexpr double kCylinderTangentCoefficient = 1.2;

}  // namespace fgsg::backend
