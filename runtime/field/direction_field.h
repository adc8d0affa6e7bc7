// What tracing asks of a field (FGSG §4.3): a unit direction in the tangent plane at any
// surface point, and the field's degenerate points. A vector field answers its vector's
// direction; a tensor field its major eigenvector, whose sign means nothing (a line
// field: u and -u are the same direction).
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <vector>

namespace fgsg::rt::field {

using surface::SurfaceMesh;
using surface::SurfacePoint;

// A degenerate (singular) point of a field, inside a face.
struct Degeneracy {
  enum Kind { Wedge, Trisector, Node, Centre, Saddle, Focus, Other };
  int face = -1;
  SurfacePoint at;
  Kind kind = Other;
  // The index: +1/2 wedge, -1/2 trisector (tensor fields), +1 node/centre/focus, -1
  // saddle (vector fields), stored doubled so it stays an integer.
  int indexTimesTwo = 0;
};

class DirectionField {
 public:
  virtual ~DirectionField() = default;
  // The unit tangent direction at p (world coordinates, orthogonal to p.normal(mesh)).
  // False where the field has no direction: a zero vector, an isotropic tensor.
  virtual bool direction(const SurfacePoint& p, Vec3& out) const = 0;
  // True for eigenvector fields of tensors: the sign of direction() is arbitrary.
  virtual bool isLineField() const = 0;
  // The degenerate points inside face f (usually none).
  virtual const std::vector<Degeneracy>& degeneraciesIn(int face) const = 0;
};

}  // namespace fgsg::rt::field
