// Bending a smooth terminal along its curve (Buron et al. 2015, §6): an instance placed
// rigidly on a marching segment (its unit box's X axis along the segment's straight chord
// from control[0] to control[3]) is deformed so that its X axis follows the curve B and
// its cross-sections turn with the curve's frame (runtime/marching/curve_frame.h).
//
// A rigid world point q (the asset point p through the instance transform M) goes to
//     B(s) + R(s) (q - chord(s)),
// where s is q's position along the chord (its projection, as a fraction of the chord:
// s = x when M's X column is the chord), chord(s) = c0 + s (c3 - c0) the point of the
// chord there, and R(s) the rotation taking the straight scope's frame onto the curve's:
//     (chord direction, scope side, scope up) -> (tangent, side, up) at s.
// The scope's up is M's Z column made orthogonal to the chord (its Y column's cross
// when Z is flat), as on a surface scope, whose Z is the normal: the scope's roll about
// its chord is replaced by the surface's, so two terminals of the same cross-section
// meet ring for ring where their segments meet, whatever their scopes' rolls. On a
// straight segment whose handles are a third of its length, with the scope's Z along the
// (constant) normal, the bend is the identity. Beyond the chord's ends (s < 0, s > 1)
// the curve continues along its end tangent and the end frame holds. Normals turn by
// R(s) — exact for a rigid motion, the usual approximation for a bend.
//
// A curve whose chord has no length bends nothing: points stay where M puts them.
#pragma once

#include "runtime/instances.h"
#include "runtime/scope.h"

#include <array>

namespace fgsg::rt::marching {

// Where a bent asset point lands and how its normals turn there.
struct BentPoint {
  Vec3 position;
  Mat3 rotation;  // applies to the rigidly transformed normal
};

class CurveBend {
 public:
  // `unitBoxToWorld`: the instance's rigid placement, column-major (Instance::transform).
  CurveBend(const CurveSegment& curve, const std::array<double, 16>& unitBoxToWorld);

  // The bent image of `local`, a point of the asset's unit box.
  BentPoint at(const Vec3& local) const;
  // The same for a point already placed rigidly in the world (M local).
  BentPoint atRigid(const Vec3& rigid) const;
  // False when the chord has no length and points stay rigid.
  bool bends() const { return length_ > 0; }

 private:
  CurveSegment curve_;
  Mat4 placement_;
  Vec3 start_, chord_;      // c0 and c3 - c0
  double length_ = 0;       // |c3 - c0|, 0: no bend
  Mat3 scopeFrame_;         // columns: chord direction, scope side, scope up
};

// One-off convenience: the bent world position of the unit-box point `local`.
Vec3 bendAlongCurve(const CurveSegment& curve, const std::array<double, 16>& unitBoxToWorld, const Vec3& local);

}  // namespace fgsg::rt::marching
