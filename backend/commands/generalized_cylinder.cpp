#include "backend/commands/generalized_cylinder.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace fgsg::backend {

namespace {

// The cubic Hermite piece from p0 (tangent m0) to p1 (tangent m1) at t in [0, 1], and its
// derivative.
struct CylinderCurvePoint {
  rt::Vec3 position, derivative;
};
CylinderCurvePoint cylinderHermite(const rt::Vec3& p0, const rt::Vec3& m0, const rt::Vec3& p1, const rt::Vec3& m1,
                                   double t) {
  const double t2 = t * t, t3 = t2 * t;
  const rt::Vec3 p = (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * m1;
  const rt::Vec3 d = (6 * t2 - 6 * t) * p0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * p1 + (3 * t2 - 2 * t) * m1;
  return {p, d};
}

// A unit vector across `t`: `hint` made square to it, or any one where hint lies along t.
rt::Vec3 cylinderAcross(const rt::Vec3& t, const rt::Vec3& hint) {
  rt::Vec3 a = hint - hint.dot(t) * t;
  if (a.norm() > 1e-9 * std::max(1.0, hint.norm())) return a.normalized();
  a = t.cross(std::abs(t.x()) < 0.9 ? rt::Vec3::UnitX() : rt::Vec3::UnitY());
  return a.normalized();
}

}  // namespace

CylinderSweep sweepGeneralizedCylinder(const std::vector<CylinderControlPoint>& points, const rt::Vec3& up,
                                       int sides) {
  CylinderSweep out;
  if (points.size() < 2 || sides < 3) return out;
  // The curve's size, for telling coinciding points from near ones.
  rt::Vec3 lo = points[0].position, hi = lo;
  for (const auto& p : points) lo = lo.cwiseMin(p.position), hi = hi.cwiseMax(p.position);
  const double tiny = 1e-12 * (hi - lo).norm();

  std::vector<double> radii;
  std::vector<rt::Vec3> acrossAt;  // each ring's vertex-0 direction, carried along by parallel transport
  auto addRing = [&](const rt::Vec3& centre, const rt::Vec3& tangent, double radius) {
    rt::Vec3 across;
    if (out.rings == 0) {
      across = cylinderAcross(tangent, up);
    } else {
      across = acrossAt.back();
      // The least rotation taking the last tangent to this one turns the frame with it. A
      // tangent turned right round (a cusp) is a half turn about `across`, which is square to both.
      const rt::Vec3 last = out.tangents.back();
      const rt::Vec3 axis = last.cross(tangent);
      const double s = axis.norm(), c = last.dot(tangent);
      if (s > 1e-12)
        across = Eigen::AngleAxisd(std::atan2(s, c), axis / s) * across;
      across = cylinderAcross(tangent, across);
    }
    out.centres.push_back(centre);
    out.tangents.push_back(tangent);
    radii.push_back(radius);
    acrossAt.push_back(across);
    ++out.rings;
  };

  const CylinderControlPoint* from = &points[0];
  addRing(from->position, from->heading.normalized(), from->radius);
  for (size_t k = 1; k < points.size(); ++k) {
    const CylinderControlPoint& to = points[k];
    const double chord = (to.position - from->position).norm();
    if (!(chord > tiny)) continue;  // no piece between coinciding points
    const rt::Vec3 m0 = kCylinderTangentCoefficient * chord * from->heading.normalized();
    const rt::Vec3 m1 = kCylinderTangentCoefficient * chord * to.heading.normalized();
    const uint32_t strips = std::max<uint32_t>(to.strips, 1);
    for (uint32_t s = 1; s <= strips; ++s) {
      const double t = double(s) / strips;
      const CylinderCurvePoint c = cylinderHermite(from->position, m0, to.position, m1, t);
      // Where the curve stops for an instant its tangent is the last one.
      const double speed = c.derivative.norm();
      const rt::Vec3 tangent = speed > 1e-12 * chord ? rt::Vec3(c.derivative / speed) : out.tangents.back();
      addRing(s == strips ? to.position : c.position, tangent, (1 - t) * from->radius + t * to.radius);
    }
    from = &to;
  }
  if (out.rings < 2) return CylinderSweep{};

  const size_t n = size_t(sides);
  out.vertices.reserve(out.rings * n);
  for (size_t r = 0; r < out.rings; ++r) {
    const rt::Vec3 a = acrossAt[r], b = out.tangents[r].cross(a);
    for (size_t j = 0; j < n; ++j) {
      const double angle = 2 * std::numbers::pi * double(j) / double(n);
      out.vertices.push_back(out.centres[r] + radii[r] * (std::cos(angle) * a + std::sin(angle) * b));
    }
  }
  // Each strip: two triangles per side, counter-clockwise seen from outside (b = t x a).
  for (size_t r = 0; r + 1 < out.rings; ++r)
    for (size_t j = 0; j < n; ++j) {
      const uint32_t v00 = uint32_t(r * n + j), v01 = uint32_t(r * n + (j + 1) % n);
      const uint32_t v10 = uint32_t((r + 1) * n + j), v11 = uint32_t((r + 1) * n + (j + 1) % n);
      out.triangles.insert(out.triangles.end(), {v00, v01, v11, v00, v11, v10});
    }
  return out;
}

}  // namespace fgsg::backend
