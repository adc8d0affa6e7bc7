#include "runtime/field/eigen_basis_direction.h"

#include <cmath>

namespace fgsg::rt::field {

namespace {

// Below this |det| of the basis's Gram matrix (1 - cos^2 of the eigenvectors' angle,
// about 0.6 degrees) the eigenvectors are taken to meet.
constexpr double kDegenerateBasis = 1e-4;

}  // namespace

bool EigenBasisDirection::coordinates(const TangentField& field, const SurfacePoint& p, const Vec3& d,
                                      double& a, double& b) {
  Vec3 dir;
  if (!field.direction(p, dir)) return false;
  const Eigen2 e = field.eigen(p);
  const double c = e.vector1.dot(e.vector2);
  const double det = 1 - c * c;
  if (!(det > kDegenerateBasis)) return false;
  const double d1 = e.vector1.dot(d), d2 = e.vector2.dot(d);
  a = (d1 - c * d2) / det;
  b = (d2 - c * d1) / det;
  return true;
}

Vec3 EigenBasisDirection::combination(const SurfacePoint& p) const {
  const Eigen2 e = field_.eigen(p);
  return a_ * e.vector1 + b_ * e.vector2;
}

bool EigenBasisDirection::direction(const SurfacePoint& p, Vec3& out) const {
  Vec3 major;
  if (!field_.direction(p, major)) return false;
  const Vec3 v = combination(p);
  const double n = v.norm();
  if (!(n > 0)) return false;
  out = v / n;
  return true;
}

}  // namespace fgsg::rt::field
