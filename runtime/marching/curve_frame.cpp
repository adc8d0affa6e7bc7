#include "runtime/marching/curve_frame.h"

#include <cmath>

namespace fgsg::rt::marching {

namespace {

Vec3 toVec3(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

// v made orthogonal to the unit vector t and normalised; false when nothing is left.
bool acrossTangent(const Vec3& v, const Vec3& t, Vec3& out) {
  const Vec3 across = v - t * t.dot(v);
  const double len = across.norm();
  if (!(len > 1e-12 * v.norm()) || !std::isfinite(len)) return false;
  out = across / len;
  return true;
}

}  // namespace

Vec3 controlPoint(const CurveSegment& curve, int index) { return toVec3(curve.control[size_t(index)]); }

Vec3 bezierPoint(const CurveSegment& curve, double x) {
  const double y = 1 - x;
  return (y * y * y) * controlPoint(curve, 0) + (3 * y * y * x) * controlPoint(curve, 1) +
         (3 * y * x * x) * controlPoint(curve, 2) + (x * x * x) * controlPoint(curve, 3);
}

Vec3 bezierDerivative(const CurveSegment& curve, double x) {
  const double y = 1 - x;
  const Vec3 c0 = controlPoint(curve, 0), c1 = controlPoint(curve, 1), c2 = controlPoint(curve, 2),
             c3 = controlPoint(curve, 3);
  return 3 * ((y * y) * (c1 - c0) + (2 * y * x) * (c2 - c1) + (x * x) * (c3 - c2));
}

CurveFrame curveFrame(const CurveSegment& curve, double x) {
  CurveFrame f;
  f.point = bezierPoint(curve, x);
  const Vec3 n0 = toVec3(curve.normal0), n1 = toVec3(curve.normal1);
  const Vec3 derivative = bezierDerivative(curve, x);
  const double dLen = derivative.norm();
  if (dLen > 0 && std::isfinite(dLen)) {
    f.tangent = derivative / dLen;
  } else {
    const Vec3 chord = controlPoint(curve, 3) - controlPoint(curve, 0);
    const double cLen = chord.norm();
    if (cLen > 0 && std::isfinite(cLen))
      f.tangent = chord / cLen;
    else  // a curve that is a point: any direction across its normal
      f.tangent = n0.squaredNorm() > 0 ? Vec3(n0.unitOrthogonal()) : Vec3(1, 0, 0);
  }
  if (!acrossTangent((1 - x) * n0 + x * n1, f.tangent, f.up) && !acrossTangent(n0, f.tangent, f.up) &&
      !acrossTangent(n1, f.tangent, f.up))
    f.up = f.tangent.unitOrthogonal();
  f.side = f.up.cross(f.tangent);
  return f;
}

}  // namespace fgsg::rt::marching
