// Moving at an angle in an asymmetric tensor field (FGSG §4.2: translation "is slightly
// more complicated for tensor fields that have arbitrary angles between eigenvectors").
// With orthogonal eigenvectors a move keeps its angle to the major one; with eigenvectors
// at any angle it keeps its coordinates in their basis instead: a move leaving along
// d = a e1 + b e2 follows a e1 + b e2 all along its curve (e1, e2 the major and minor
// eigenvectors, e2 on e1's counter-clockwise side), so a move along the minor
// eigenvector stays on it, and where the eigenvectors are orthogonal the two rules agree.
#pragma once

#include "runtime/field/tangent_field.h"

namespace fgsg::rt::field {

class EigenBasisDirection final : public DirectionField {
 public:
  EigenBasisDirection(const TangentField& field, double a, double b) : field_(field), a_(a), b_(b) {}

  // The coordinates (a, b) of tangent vector d in the eigenvector basis at p. False where
  // the basis does not span the plane (the eigenvectors meet, or the field has no
  // direction there): the caller keeps the angle to e1 instead.
  static bool coordinates(const TangentField& field, const SurfacePoint& p, const Vec3& d, double& a, double& b);
  // a e1 + b e2 at p (not normalised; its sign follows e1's, which is arbitrary).
  Vec3 combination(const SurfacePoint& p) const;

  bool direction(const SurfacePoint& p, Vec3& out) const override;
  bool isLineField() const override { return true; }
  const std::vector<Degeneracy>& degeneraciesIn(int face) const override { return field_.degeneraciesIn(face); }

 private:
  const TangentField& field_;
  double a_, b_;
};

}  // namespace fgsg::rt::field
