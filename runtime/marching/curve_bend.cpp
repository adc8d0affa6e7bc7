#include "runtime/marching/curve_bend.h"

#include "runtime/marching/curve_frame.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::marching {

namespace {

// v made orthogonal to the unit vector d and normalised; false when (nearly) nothing is
// left, e.g. a column flattened to zero or lying along the chord.
bool acrossUnit(const Vec3& v, const Vec3& d, Vec3& out) {
  const Vec3 across = v - d * d.dot(v);
  const double len = across.norm();
  if (!(len > 1e-9 * v.norm()) || !std::isfinite(len)) return false;
  out = across / len;
  return true;
}

}  // namespace

CurveBend::CurveBend(const CurveSegment& curve, const std::array<double, 16>& unitBoxToWorld)
    : curve_(curve), placement_(Eigen::Map<const Mat4>(unitBoxToWorld.data())) {
  start_ = controlPoint(curve, 0);
  chord_ = controlPoint(curve, 3) - start_;
  const double length = chord_.norm();
  scopeFrame_.setIdentity();
  if (!(length > 0) || !std::isfinite(length)) return;
  length_ = length;
  const Vec3 along = chord_ / length;
  // The scope's up: its Z column across the chord; a flat Z: X x Y (Y = Z x X on a
  // scope); a flat box: the surface normal at the start; else anything across.
  Vec3 up;
  Vec3 side;
  if (!acrossUnit(placement_.block<3, 1>(0, 2), along, up)) {
    if (acrossUnit(placement_.block<3, 1>(0, 1), along, side))
      up = along.cross(side);
    else if (!acrossUnit(Vec3(curve.normal0[0], curve.normal0[1], curve.normal0[2]), along, up))
      up = along.unitOrthogonal();
  }
  scopeFrame_.col(0) = along;
  scopeFrame_.col(1) = up.cross(along);
  scopeFrame_.col(2) = up;
  // s = (M local - c0) . chord / |chord|^2, as an affine function of local.
  for (int k = 0; k < 3; ++k) {
    const Vec3 column = placement_.block<3, 1>(0, k);
    const double dot = column.dot(chord_);
    if (std::abs(dot) > 1e-12 * column.norm() * length) along_[k] = dot / (length * length);
  }
  alongAt0_ = (placement_.block<3, 1>(0, 3) - start_).dot(chord_) / (length * length);
  scopeLinear_ = scopeFrame_.transpose() * placement_.block<3, 3>(0, 0);
  scopeOffset_ = scopeFrame_.transpose() * (placement_.block<3, 1>(0, 3) - start_);
  scopeChord_ = scopeFrame_.transpose() * chord_;
}

void CurveBend::curveAt(double s, Mat3& frame, Vec3& onCurve) const {
  const double x = std::clamp(s, 0.0, 1.0);
  const CurveFrame f = curveFrame(curve_, x);
  frame.col(0) = f.tangent;
  frame.col(1) = f.side;
  frame.col(2) = f.up;
  // Beyond an end, straight on along the end tangent (B is only followed on [0, 1]).
  onCurve = s == x ? f.point : Vec3(f.point + (s - x) * bezierDerivative(curve_, x));
}

CurveBend::SectionMap CurveBend::sectionMap(double s) const {
  if (length_ == 0) return {placement_.block<3, 3>(0, 0), placement_.block<3, 1>(0, 3), Mat3::Identity()};
  SectionMap out;
  Vec3 onCurve;
  curveAt(s, out.frame, onCurve);
  out.linear = out.frame * scopeLinear_;
  out.offset = out.frame * (scopeOffset_ - s * scopeChord_) + onCurve;
  return out;
}

BentPoint CurveBend::at(const Vec3& local) const {
  return place(section(along(local)), placement_.block<3, 3>(0, 0) * local + placement_.block<3, 1>(0, 3));
}

BentPoint CurveBend::atRigid(const Vec3& rigid) const {
  if (length_ == 0) return {rigid, Mat3::Identity()};
  return place(section((rigid - start_).dot(chord_) / (length_ * length_)), rigid);
}

BendSection CurveBend::section(double s) const {
  BendSection out;
  out.s = s;
  if (length_ == 0) return out;
  Mat3 frame;
  curveAt(s, frame, out.onCurve);
  out.rotation = frame * scopeFrame_.transpose();
  out.chordPoint = start_ + s * chord_;
  return out;
}

Vec3 bendAlongCurve(const CurveSegment& curve, const std::array<double, 16>& unitBoxToWorld, const Vec3& local) {
  return CurveBend(curve, unitBoxToWorld).at(local).position;
}

}  // namespace fgsg::rt::marching
