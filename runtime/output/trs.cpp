#include "runtime/output/trs.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace fgsg::rt::output {

TrsFit decomposeTrs(const std::array<double, 16>& m, Trs& trs, int flatAxis) {
  for (double x : m)
    if (!std::isfinite(x)) return TrsFit::Degenerate;
  if (m[3] != 0 || m[7] != 0 || m[11] != 0 || m[15] != 1) return TrsFit::Sheared;
  const Eigen::Map<const Eigen::Matrix4d> M(m.data());
  Eigen::Matrix3d A = M.block<3, 3>(0, 0);
  Eigen::Vector3d s(A.col(0).norm(), A.col(1).norm(), A.col(2).norm());
  const double longest = s.maxCoeff();
  if (flatAxis >= 0 && flatAxis < 3 && !(s[flatAxis] > kFlatScale * longest)) {
    const int a = (flatAxis + 1) % 3, b = (flatAxis + 2) % 3;
    const Eigen::Vector3d n = A.col(a).cross(A.col(b));
    if (!(n.norm() > kFlatScale * longest * longest)) return TrsFit::Degenerate;
    A.col(flatAxis) = n.normalized();
    s[flatAxis] = 1;
  }
  if (!(s.minCoeff() > kFlatScale * longest)) return TrsFit::Degenerate;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(A.col(i).dot(A.col(j))) > kOrthogonalCosine * s[i] * s[j]) return TrsFit::Sheared;
  Eigen::Matrix3d R;
  for (int k = 0; k < 3; ++k) R.col(k) = A.col(k) / s[k];
  const bool mirrored = R.determinant() < 0;
  if (mirrored) R.col(0) = -R.col(0), s[0] = -s[0];
  Eigen::Quaterniond q(R);
  q.normalize();
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  trs.translation = {m[12], m[13], m[14]};
  trs.rotation = {q.x(), q.y(), q.z(), q.w()};
  trs.scale = {s[0], s[1], s[2]};
  return mirrored ? TrsFit::Mirrored : TrsFit::Rigid;
}

std::array<double, 16> composeTrs(const Trs& trs) {
  const Eigen::Quaterniond q(trs.rotation[3], trs.rotation[0], trs.rotation[1], trs.rotation[2]);
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  std::array<double, 16> m{};
  Eigen::Map<Eigen::Matrix4d> M(m.data());
  M.setIdentity();
  for (int k = 0; k < 3; ++k) M.block<3, 1>(0, k) = R.col(k) * trs.scale[k];
  M.block<3, 1>(0, 3) = Eigen::Vector3d(trs.translation[0], trs.translation[1], trs.translation[2]);
  return m;
}

}  // namespace fgsg::rt::output
