#include "runtime/lines/tube.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fgsg::rt {
namespace {

// Centripetal parameterisation: knot intervals are the square roots of the chord lengths.
constexpr double kAlpha = 0.5;

// Point at fraction u of the span p1 -> p2 of the Catmull–Rom spline through p0 p1 p2 p3,
// by the Barry–Goldman pyramid (valid for any knot spacing).
Vec3 catmullRom(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, double u) {
  const double d12 = std::pow((p2 - p1).norm(), kAlpha);
  // A repeated neighbour has no chord of its own: borrow the span's, which keeps the
  // pyramid's divisions defined.
  double d01 = std::pow((p1 - p0).norm(), kAlpha), d23 = std::pow((p3 - p2).norm(), kAlpha);
  if (!(d01 > 0)) d01 = d12;
  if (!(d23 > 0)) d23 = d12;
  const double t0 = 0, t1 = d01, t2 = t1 + d12, t3 = t2 + d23;
  const double t = t1 + u * d12;
  const Vec3 a1 = ((t1 - t) * p0 + (t - t0) * p1) / (t1 - t0);
  const Vec3 a2 = ((t2 - t) * p1 + (t - t1) * p2) / (t2 - t1);
  const Vec3 a3 = ((t3 - t) * p2 + (t - t2) * p3) / (t3 - t2);
  const Vec3 b1 = ((t2 - t) * a1 + (t - t0) * a2) / (t2 - t0);
  const Vec3 b2 = ((t3 - t) * a2 + (t - t1) * a3) / (t3 - t1);
  return ((t2 - t) * b1 + (t - t1) * b2) / (t2 - t1);
}

// Any unit vector perpendicular to unit `t`: from the world axis least aligned with it
// (the first such axis on ties), so the same tangent always gives the same start frame.
Vec3 perpendicular(const Vec3& t) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(t[k]) < std::abs(t[axis])) axis = k;
  const Vec3 e = Vec3::Unit(axis);
  return (e - e.dot(t) * t).normalized();
}

void push(MeshArray<float>& v, const Vec3& p) {
  v.push_back(float(p.x()));
  v.push_back(float(p.y()));
  v.push_back(float(p.z()));
}

}  // namespace

std::vector<Vec3> sampleCentreline(const std::vector<Vec3>& points, int samplesPerSegment) {
  const size_t n = points.size();
  if (n < 2) return points;
  const int per = std::max(1, samplesPerSegment);
  std::vector<Vec3> out;
  out.reserve((n - 1) * per + 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    const Vec3& p1 = points[i];
    const Vec3& p2 = points[i + 1];
    out.push_back(p1);  // exact, not evaluated: knots stay where the line put them
    if ((p2 - p1).norm() == 0) {
      for (int j = 1; j < per; ++j) out.push_back(p1);
      continue;
    }
    // Beyond the ends the line continues straight (a reflected neighbour).
    const Vec3 p0 = i > 0 ? points[i - 1] : Vec3(2 * p1 - p2);
    const Vec3 p3 = i + 2 < n ? points[i + 2] : Vec3(2 * p2 - p1);
    for (int j = 1; j < per; ++j) out.push_back(catmullRom(p0, p1, p2, p3, double(j) / per));
  }
  out.push_back(points.back());
  return out;
}

Mesh sweepTube(const std::vector<Vec3>& points, double radius, int sides, int samplesPerSegment) {
  Mesh mesh;
  if (points.size() < 2 || !(radius > 0)) return mesh;
  sides = std::max(3, sides);
  const std::vector<Vec3> x = sampleCentreline(points, samplesPerSegment);
  const size_t count = x.size();

  // Tangents by central differences (one-sided at the ends); where the difference
  // vanishes (a sharp reversal) the previous tangent carries on.
  std::vector<Vec3> tangent(count);
  for (size_t i = 0; i < count; ++i) {
    const Vec3 d = x[std::min(i + 1, count - 1)] - x[i > 0 ? i - 1 : 0];
    const double len = d.norm();
    tangent[i] = len > 0 ? Vec3(d / len) : i > 0 ? tangent[i - 1] : Vec3::UnitX();
  }

  // Frames by parallel transport, with the double reflection method (Wang et al. 2008):
  // rotation-minimising, so the rings do not twist about the centreline.
  std::vector<Vec3> normal(count);
  normal[0] = perpendicular(tangent[0]);
  for (size_t i = 0; i + 1 < count; ++i) {
    const Vec3 v1 = x[i + 1] - x[i];
    const double c1 = v1.squaredNorm();
    Vec3 r = normal[i], t = tangent[i];
    if (c1 > 0) {
      r -= (2 / c1) * v1.dot(r) * v1;
      t -= (2 / c1) * v1.dot(t) * v1;
    }
    const Vec3 v2 = tangent[i + 1] - t;
    const double c2 = v2.squaredNorm();
    if (c2 > 0) r -= (2 / c2) * v2.dot(r) * v2;
    // Re-orthogonalise, so rounding does not build up along long lines.
    const Vec3 u = r - r.dot(tangent[i + 1]) * tangent[i + 1];
    normal[i + 1] = u.norm() > 0 ? Vec3(u.normalized()) : perpendicular(tangent[i + 1]);
  }

  std::vector<double> cosines(sides), sines(sides);
  for (int k = 0; k < sides; ++k) {
    cosines[k] = std::cos(2 * std::numbers::pi * k / sides);
    sines[k] = std::sin(2 * std::numbers::pi * k / sides);
  }
  auto ringOffset = [&](size_t i, int k) {
    const Vec3 b = tangent[i].cross(normal[i]);  // (N, B, T) right-handed
    return Vec3(cosines[k] * normal[i] + sines[k] * b);
  };

  const size_t vertices = count * sides + 2 * (sides + 1);
  mesh.positions.reserve(3 * vertices);
  mesh.normals.reserve(3 * vertices);
  for (size_t i = 0; i < count; ++i)
    for (int k = 0; k < sides; ++k) {
      const Vec3 o = ringOffset(i, k);
      push(mesh.positions, x[i] + radius * o);
      push(mesh.normals, o);
    }
  // Caps reuse the end rings' float positions exactly, so the seams close by position.
  auto addCap = [&](size_t i, const Vec3& n) {
    const uint32_t centre = uint32_t(mesh.vertexCount());
    push(mesh.positions, x[i]);
    push(mesh.normals, n);
    for (int k = 0; k < sides; ++k) {
      for (int c = 0; c < 3; ++c) {
        const float coordinate = mesh.positions[3 * (i * sides + k) + c];
        mesh.positions.push_back(coordinate);
      }
      push(mesh.normals, n);
    }
    return centre;
  };
  const uint32_t startCap = addCap(0, -tangent[0]);
  const uint32_t endCap = addCap(count - 1, tangent[count - 1]);

  mesh.indices.reserve(3 * 2 * sides * count);
  auto tri = [&](uint32_t a, uint32_t b, uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  };
  // Going round k turns from N towards B, counter-clockwise about T: (a, b, c) below has
  // its face normal along (around) x T, which points outwards.
  for (size_t i = 0; i + 1 < count; ++i)
    for (int k = 0; k < sides; ++k) {
      const uint32_t k1 = (k + 1) % sides;
      const uint32_t a = uint32_t(i * sides + k), b = uint32_t(i * sides + k1);
      const uint32_t c = uint32_t((i + 1) * sides + k1), d = uint32_t((i + 1) * sides + k);
      tri(a, b, c);
      tri(a, c, d);
    }
  for (int k = 0; k < sides; ++k) {
    const uint32_t k1 = (k + 1) % sides;
    tri(startCap, startCap + 1 + k1, startCap + 1 + k);  // faces -T
    tri(endCap, endCap + 1 + k, endCap + 1 + k1);        // faces +T
  }
  return mesh;
}

}  // namespace fgsg::rt
