// Bending terminals along smooth curves (runtime/marching/curve_frame.h, curve_bend.h):
// the frame, the identity on straight segments, joints without cracks, the chord's
// points onto the curve, beyond the ends, flat chords, and rings sharing a section.
#include "runtime/marching/curve_bend.h"
#include "runtime/marching/curve_frame.h"
#include "runtime/marching/smooth_curves.h"

#include "tests/unit/marching/march_graphs.h"

#include <catch2/catch.hpp>

#include <random>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using fgsg::test::Graph;

namespace {

// The placement of a terminal on a segment: X along the chord, Z the scope's up (`up`
// made orthogonal to the chord), Y = Z x X; a cross-section `width` x `height` centred
// on the chord.
std::array<double, 16> scopeOnChord(const CurveSegment& c, const Vec3& up, double width, double height) {
  const Vec3 a = controlPoint(c, 0), chord = controlPoint(c, 3) - a;
  const Vec3 X = chord.normalized();
  const Vec3 Z = (up - X * X.dot(up)).normalized(), Y = Z.cross(X);
  Mat4 m = Mat4::Identity();
  m.block<3, 1>(0, 0) = chord;
  m.block<3, 1>(0, 1) = width * Y;
  m.block<3, 1>(0, 2) = height * Z;
  m.block<3, 1>(0, 3) = a - 0.5 * width * Y - 0.5 * height * Z;
  std::array<double, 16> out;
  Eigen::Map<Mat4>(out.data()) = m;
  return out;
}

Vec3 rigid(const std::array<double, 16>& t, const Vec3& local) {
  const Eigen::Map<const Mat4> m(t.data());
  return m.block<3, 3>(0, 0) * local + m.block<3, 1>(0, 3);
}

// The outward normal of the cylinder below at its vertex `local`, rigidly placed by t
// (whose Y and Z columns are orthogonal and of one length).
Vec3 ringNormal(const std::array<double, 16>& t, const Vec3& local) {
  const Eigen::Map<const Mat4> m(t.data());
  return ((local.y() - 0.5) * m.block<3, 1>(0, 1) + (local.z() - 0.5) * m.block<3, 1>(0, 2)).normalized();
}

// The vertices of a unit cylinder along X at x: a ring of `n` about (x, 0.5, 0.5).
std::vector<Vec3> ring(double x, int n) {
  std::vector<Vec3> out;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    out.emplace_back(x, 0.5 + 0.5 * std::cos(a), 0.5 + 0.5 * std::sin(a));
  }
  return out;
}

}  // namespace

TEST_CASE("the frame along a curve is orthonormal and right-handed like a surface scope", "[bend]") {
  const Graph g = fgsg::test::sphereWalk(5, 20, 2.0);
  for (const CurveSegment& c : smoothSegments(g.nodes, g.segments))
    for (double x : {0.0, 0.3, 0.5, 1.0}) {
      const CurveFrame f = curveFrame(c, x);
      CHECK(f.tangent.norm() == Approx(1).epsilon(1e-14));
      CHECK(f.up.norm() == Approx(1).epsilon(1e-14));
      CHECK(std::abs(f.tangent.dot(f.up)) < 1e-14);
      CHECK((f.tangent.cross(f.side) - f.up).norm() < 1e-14);  // (tangent, side, up) ~ (X, Y, Z)
      CHECK((f.tangent - bezierDerivative(c, x).normalized()).norm() < 1e-15);
    }
  // At the ends, up is the node's normal.
  const CurveSegment c = smoothSegments(g.nodes, g.segments)[3];
  CHECK((curveFrame(c, 0.0).up - Vec3(c.normal0[0], c.normal0[1], c.normal0[2])).norm() < 1e-12);
  CHECK((curveFrame(c, 1.0).up - Vec3(c.normal1[0], c.normal1[1], c.normal1[2])).norm() < 1e-12);
}

TEST_CASE("bending along a straight polyline on a plane is the identity", "[bend]") {
  const Vec3 n = Vec3(-0.1, 0.25, 1).normalized();
  const Vec3 dir = (Vec3(1, 0.5, 0) - n * n.dot(Vec3(1, 0.5, 0))).normalized();
  Graph g;
  for (int i = 0; i < 4; ++i) g.add(Vec3(-2, 1, 0.5) + 1.25 * i * dir, n);
  for (uint32_t i = 0; i + 1 < 4; ++i) g.join(i, i + 1);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  for (const CurveSegment& c : smoothSegments(g.nodes, g.segments)) {
    const std::array<double, 16> t = scopeOnChord(c, n, 0.3, 0.2);
    const CurveBend bend(c, t);
    REQUIRE(bend.bends());
    for (int k = 0; k < 50; ++k) {
      const Vec3 local(unit(rng), unit(rng), unit(rng));
      const BentPoint b = bend.at(local);
      CHECK((b.position - rigid(t, local)).norm() < 1e-12);
      CHECK((b.rotation - Mat3::Identity()).norm() < 1e-12);
      CHECK((bendAlongCurve(c, t, local) - b.position).norm() == 0);
    }
  }
}

TEST_CASE("bent cylinders on consecutive segments meet ring for ring", "[bend]") {
  const Graph g = fgsg::test::sphereWalk(21, 8, 1.0);
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (size_t s = 0; s + 1 < curves.size(); ++s) {
    INFO("joint after segment " << s);
    // The scopes' rolls differ: the first stands on its start normal, the second is
    // turned about its chord by a random angle; the rings still meet.
    const Vec3 n0(curves[s].normal0[0], curves[s].normal0[1], curves[s].normal0[2]);
    const Vec3 n1(curves[s + 1].normal0[0], curves[s + 1].normal0[1], curves[s + 1].normal0[2]);
    const Vec3 axis = (controlPoint(curves[s + 1], 3) - controlPoint(curves[s + 1], 0)).normalized();
    const Vec3 rolled = Eigen::AngleAxisd(angle(rng), axis) * n1;
    const std::array<double, 16> t1 = scopeOnChord(curves[s], n0, 0.04, 0.04);
    const std::array<double, 16> t2 = scopeOnChord(curves[s + 1], rolled, 0.04, 0.04);
    const CurveBend first(curves[s], t1), second(curves[s + 1], t2);
    const std::vector<Vec3> end = ring(1.0, 16), start = ring(0.0, 16);
    for (size_t k = 0; k < end.size(); ++k) {
      const BentPoint a = first.at(end[k]), b = second.at(start[k]);
      CHECK((a.position - b.position).norm() < 1e-9);
      // The cylinder's outward normals there turn alike, so shading has no seam either.
      CHECK((a.rotation * ringNormal(t1, end[k]) - b.rotation * ringNormal(t2, start[k])).norm() < 1e-9);
    }
    // The ring lies in the plane across the curve at the node, at the cylinder's radius.
    const CurveFrame f = curveFrame(curves[s + 1], 0.0);
    for (const Vec3& p : start) {
      const Vec3 q = second.at(p).position - f.point;
      CHECK(std::abs(q.dot(f.tangent)) < 1e-12);
      CHECK(q.norm() == Approx(0.02).epsilon(1e-9));
    }
  }
}

TEST_CASE("bending maps the chord onto the curve and turns normals with the frame", "[bend]") {
  const Graph g = fgsg::test::sphereWalk(4, 6, 1.0);
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  const CurveSegment& c = curves[2];
  const Vec3 n0(c.normal0[0], c.normal0[1], c.normal0[2]);
  const std::array<double, 16> t = scopeOnChord(c, n0, 0.1, 0.06);
  const CurveBend bend(c, t);
  const Eigen::Map<const Mat4> m(t.data());
  const Vec3 X = m.block<3, 1>(0, 0).normalized(), Y = m.block<3, 1>(0, 1).normalized(),
             Z = m.block<3, 1>(0, 2).normalized();
  for (double x : {0.0, 0.2, 0.5, 0.8, 1.0}) {
    const CurveFrame f = curveFrame(c, x);
    const BentPoint onChord = bend.at(Vec3(x, 0.5, 0.5));
    CHECK((onChord.position - f.point).norm() < 1e-12);
    // The scope's axes turn onto the frame: X -> tangent, Y -> side, Z -> up.
    CHECK((onChord.rotation * X - f.tangent).norm() < 1e-12);
    CHECK((onChord.rotation * Y - f.side).norm() < 1e-12);
    CHECK((onChord.rotation * Z - f.up).norm() < 1e-12);
    // A point on the top face lands on the frame's up side, 0.03 off the curve.
    const BentPoint top = bend.at(Vec3(x, 0.5, 1.0));
    CHECK((top.position - (f.point + 0.03 * f.up)).norm() < 1e-12);
    const BentPoint right = bend.at(Vec3(x, 1.0, 0.5));
    CHECK((right.position - (f.point + 0.05 * f.side)).norm() < 1e-12);
  }
}

TEST_CASE("beyond the chord's ends a bent terminal goes straight on", "[bend]") {
  const Graph g = fgsg::test::sphereWalk(8, 3, 1.0);
  const CurveSegment c = smoothSegments(g.nodes, g.segments)[1];
  const Vec3 n0(c.normal0[0], c.normal0[1], c.normal0[2]);
  const CurveBend bend(c, scopeOnChord(c, n0, 0.1, 0.1));
  const CurveFrame end = curveFrame(c, 1.0), start = curveFrame(c, 0.0);
  CHECK((bend.at(Vec3(1.25, 0.5, 0.5)).position - (end.point + 0.25 * bezierDerivative(c, 1.0))).norm() < 1e-12);
  CHECK((bend.at(Vec3(-0.5, 0.5, 1.0)).position -
         (start.point - 0.5 * bezierDerivative(c, 0.0) + 0.05 * start.up)).norm() < 1e-12);
}

TEST_CASE("a curve without a chord leaves its terminal rigid", "[bend]") {
  CurveSegment c;
  for (auto& p : c.control) p = {1, 2, 3};
  c.normal0 = c.normal1 = {0, 0, 1};
  std::array<double, 16> t{};
  Eigen::Map<Mat4>(t.data()) = Mat4::Identity();
  const CurveBend bend(c, t);
  CHECK_FALSE(bend.bends());
  const BentPoint b = bend.at(Vec3(0.3, 0.4, 0.5));
  CHECK(b.position == Vec3(0.3, 0.4, 0.5));
  CHECK(b.rotation == Mat3::Identity());
  // And its frame is still a frame.
  const CurveFrame f = curveFrame(c, 0.5);
  CHECK(f.point == Vec3(1, 2, 3));
  CHECK(f.up == Vec3(0, 0, 1));
  CHECK(std::abs(f.tangent.dot(f.up)) < 1e-15);
}

TEST_CASE("the points of a ring across the chord share one section", "[bend]") {
  const Graph g = fgsg::test::sphereWalk(6, 8, 1.0);
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  for (size_t i = 0; i < curves.size(); ++i) {
    INFO("curve " << i);
    const CurveSegment& c = curves[i];
    const Vec3 n0(c.normal0[0], c.normal0[1], c.normal0[2]);
    const std::array<double, 16> t = scopeOnChord(c, n0, 0.04, 0.07);
    const CurveBend bend(c, t);
    for (double x : {-0.25, 0.0, 0.3, 0.7, 1.0, 1.5}) {
      const std::vector<Vec3> points = ring(x, 9);
      const double s = bend.along(points[0]);
      CHECK(s == Approx(x).margin(1e-12));
      const BendSection shared = bend.section(s);
      for (const Vec3& p : points) {
        CHECK(bend.along(p) == s);  // exactly: Y and Z add nothing to s
        // One section for the ring gives at()'s result exactly, and atRigid's (s projected
        // from the world point) up to rounding.
        const BentPoint b = bend.place(shared, rigid(t, p));
        const BentPoint a = bend.at(p), r = bend.atRigid(rigid(t, p));
        CHECK(b.position == a.position);
        CHECK(b.rotation == a.rotation);
        CHECK((b.position - r.position).norm() < 1e-12);
        CHECK((b.rotation - r.rotation).norm() < 1e-12);
      }
    }
    // A scope sheared along its chord: its Y column does add to s, and at() agrees with
    // atRigid as before.
    std::array<double, 16> sheared = t;
    for (int k = 0; k < 3; ++k) sheared[4 + k] += 0.3 * sheared[k];
    const CurveBend shearedBend(c, sheared);
    const Vec3 p(0.5, 1.0, 0.5), q(0.5, 0.0, 0.5);
    CHECK(shearedBend.along(p) - shearedBend.along(q) == Approx(0.3));
    CHECK((shearedBend.at(p).position - shearedBend.atRigid(rigid(sheared, p)).position).norm() < 1e-12);
  }
}

TEST_CASE("a section's affine map places a ring as place(section) does, and turns its normals alike", "[bend]") {
  const Graph g = fgsg::test::sphereWalk(5, 6, 1.0);
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (size_t i = 0; i < curves.size(); ++i) {
    INFO("curve " << i);
    const CurveSegment& c = curves[i];
    const std::array<double, 16> t = scopeOnChord(c, Vec3(unit(rng), unit(rng), unit(rng)), 0.03, 0.05);
    const CurveBend bend(c, t);
    const Eigen::Map<const Mat4> m(t.data());
    for (double x : {-0.5, 0.0, 0.4, 1.0, 1.25}) {
      const CurveBend::SectionMap map = bend.sectionMap(x);
      const BendSection section = bend.section(x);
      // The turn of normals: frame * scopeFrame^T is the section's rotation.
      CHECK((map.frame * bend.scopeFrame().transpose() - section.rotation).norm() < 1e-14);
      for (const Vec3& p : ring(x, 7)) {
        const Vec3 expected = bend.place(section, m.block<3, 3>(0, 0) * p + m.block<3, 1>(0, 3)).position;
        CHECK((map.linear * p + map.offset - expected).norm() < 1e-14);
      }
    }
  }
  // A chord of no length bends nothing: the map is the placement itself.
  CurveSegment point;
  const std::array<double, 16> t = scopeOnChord(curves[0], Vec3(0, 0, 1), 0.03, 0.05);
  const CurveBend still(point, t);
  const CurveBend::SectionMap map = still.sectionMap(0.5);
  CHECK(map.linear == Eigen::Map<const Mat4>(t.data()).block<3, 3>(0, 0));
  CHECK(map.frame == Mat3::Identity());
}
