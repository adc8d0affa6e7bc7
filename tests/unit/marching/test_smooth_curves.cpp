// Smooth terminals' curves (runtime/marching/smooth_curves.h): ends on the nodes, tangent
// to the surface, C1 where segments meet (continuations, branches, seeds), straight on
// straight polylines.
#include "runtime/marching/curve_frame.h"
#include "runtime/marching/smooth_curves.h"

#include "tests/unit/marching/march_graphs.h"

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using fgsg::test::Graph;

namespace {

Vec3 control(const CurveSegment& c, int i) { return controlPoint(c, i); }
Vec3 normal0(const CurveSegment& c) { return Vec3(c.normal0[0], c.normal0[1], c.normal0[2]); }
Vec3 normal1(const CurveSegment& c) { return Vec3(c.normal1[0], c.normal1[1], c.normal1[2]); }
Vec3 P(const Vec3& n, const Vec3& v) { return v - n * n.dot(v); }

}  // namespace

TEST_CASE("smooth curves start and end exactly on their nodes", "[smooth]") {
  const Graph g = fgsg::test::sphereWalk(7, 40, 2.0);
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  REQUIRE(curves.size() == g.segments.size());
  for (size_t s = 0; s < curves.size(); ++s) {
    const Vec3 a = g.nodes[g.segments[s].from].position, b = g.nodes[g.segments[s].to].position;
    CHECK(control(curves[s], 0) == a);
    CHECK(control(curves[s], 3) == b);
    CHECK(bezierPoint(curves[s], 0.0) == a);
    CHECK(bezierPoint(curves[s], 1.0) == b);
    CHECK(normal0(curves[s]) == g.nodes[g.segments[s].from].normal);
    CHECK(normal1(curves[s]) == g.nodes[g.segments[s].to].normal);
  }
}

TEST_CASE("smooth curves are C1 and tangent to a sphere along a random polyline", "[smooth]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Graph g = fgsg::test::sphereWalk(seed, 60, 2.0);
    const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
    for (size_t s = 0; s + 1 < curves.size(); ++s) {
      INFO("seed " << seed << ", joint after segment " << s);
      const Vec3 in = bezierDerivative(curves[s], 1.0), out = bezierDerivative(curves[s + 1], 0.0);
      CHECK((in - out).norm() < 1e-9);
      CHECK(in.norm() > 1e-3);
      // The frames agree, so bent terminals join.
      const CurveFrame f1 = curveFrame(curves[s], 1.0), f2 = curveFrame(curves[s + 1], 0.0);
      CHECK((f1.point - f2.point).norm() < 1e-9);
      CHECK((f1.tangent - f2.tangent).norm() < 1e-9);
      CHECK((f1.up - f2.up).norm() < 1e-9);
      CHECK((f1.side - f2.side).norm() < 1e-9);
    }
    for (const CurveSegment& c : curves) {
      // In the tangent plane at both ends, and the handles within a third of the chord.
      const double chord = (control(c, 3) - control(c, 0)).norm();
      CHECK(std::abs((control(c, 1) - control(c, 0)).dot(normal0(c))) < 1e-12);
      CHECK(std::abs((control(c, 3) - control(c, 2)).dot(normal1(c))) < 1e-12);
      CHECK((control(c, 1) - control(c, 0)).norm() <= chord / 3 + 1e-12);
      CHECK((control(c, 3) - control(c, 2)).norm() <= chord / 3 + 1e-12);
      CHECK(std::abs(curveFrame(c, 0.0).tangent.dot(normal0(c))) < 1e-12);
      CHECK(std::abs(curveFrame(c, 1.0).tangent.dot(normal1(c))) < 1e-12);
    }
  }
}

TEST_CASE("an inner node's tangent is the paper's: the projected sum of the segment directions", "[smooth]") {
  const Graph g = fgsg::test::sphereWalk(11, 5, 1.5);
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  for (size_t i = 1; i + 1 < g.nodes.size(); ++i) {
    const Vec3 p = g.nodes[i].position, n = g.nodes[i].normal;
    const Vec3 prev = g.nodes[i - 1].position, next = g.nodes[i + 1].position;
    const Vec3 t = P(n, (p - prev).normalized() + (next - p).normalized()).normalized();
    const double h = std::min(0.5 * (std::abs(t.dot(p - prev)) + std::abs(t.dot(next - p))),
                              std::min((p - prev).norm(), (next - p).norm())) / 3;
    CHECK((control(curves[i], 1) - (p + h * t)).norm() < 1e-12);
    CHECK((control(curves[i - 1], 2) - (p - h * t)).norm() < 1e-12);
  }
  // At the ends, the one segment's own direction, projected.
  const Vec3 a = g.nodes[0].position, b = g.nodes[1].position, n = g.nodes[0].normal;
  const Vec3 t = P(n, b - a).normalized();
  CHECK((control(curves[0], 1) - (a + std::abs(t.dot(b - a)) / 3 * t)).norm() < 1e-12);
}

TEST_CASE("a branch node gives all three of its curves one derivative", "[smooth]") {
  Graph g;
  const double r = 3.0;
  const uint32_t a = g.add(fgsg::test::onSphere(Vec3(-0.4, 0.05, 1), r), Vec3(-0.4, 0.05, 1));
  const uint32_t b = g.add(Vec3(0, 0, r), Vec3(0, 0, 1));
  const uint32_t c = g.add(fgsg::test::onSphere(Vec3(0.3, -0.1, 1), r), Vec3(0.3, -0.1, 1));
  const uint32_t d = g.add(fgsg::test::onSphere(Vec3(0.2, 0.35, 1), r), Vec3(0.2, 0.35, 1));
  g.join(a, b);  // into the branch point
  g.join(b, c);  // the main branch on
  g.join(b, d);  // the side branch
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  const Vec3 in = bezierDerivative(curves[0], 1.0);
  CHECK((bezierDerivative(curves[1], 0.0) - in).norm() < 1e-9);
  CHECK((bezierDerivative(curves[2], 0.0) - in).norm() < 1e-9);
  // The average over all three, projected: in the tangent plane z = const at b.
  const Vec3 pb = g.nodes[b].position;
  const Vec3 sum = (pb - g.nodes[a].position).normalized() + (g.nodes[c].position - pb).normalized() +
                   (g.nodes[d].position - pb).normalized();
  const Vec3 t = P(Vec3(0, 0, 1), sum).normalized();
  CHECK((in.normalized() - t).norm() < 1e-12);
  CHECK(std::abs(in.z()) < 1e-12);
  for (int k = 1; k < 3; ++k) {
    const CurveFrame f = curveFrame(curves[size_t(k)], 0.0), f0 = curveFrame(curves[0], 1.0);
    CHECK((f.tangent - f0.tangent).norm() < 1e-9);
    CHECK((f.up - f0.up).norm() < 1e-9);
  }
}

TEST_CASE("a straight evenly spaced polyline on a plane gives straight curves at thirds", "[smooth]") {
  const Vec3 n = Vec3(0.2, -0.3, 1).normalized();
  const Vec3 dir = n.unitOrthogonal();
  Graph g;
  for (int i = 0; i < 5; ++i) g.add(Vec3(1, 2, 3) + 0.7 * i * dir, n);
  for (uint32_t i = 0; i + 1 < 5; ++i) g.join(i, i + 1);
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  for (const CurveSegment& c : curves) {
    const Vec3 a = control(c, 0), b = control(c, 3);
    CHECK((control(c, 1) - (a + (b - a) / 3)).norm() < 1e-12);
    CHECK((control(c, 2) - (b - (b - a) / 3)).norm() < 1e-12);
    for (double x : {0.1, 0.25, 0.5, 0.9}) CHECK((bezierPoint(c, x) - (a + x * (b - a))).norm() < 1e-12);
  }
}

TEST_CASE("a seed growing two ways is one smooth curve through it", "[smooth]") {
  const Vec3 n(0, 0, 1);
  SECTION("opposite directions: straight through") {
    Graph g;
    const uint32_t seed = g.add(Vec3(0, 0, 0), n);
    g.add(Vec3(1, 0, 0), n);
    g.add(Vec3(-0.5, 0, 0), n);
    g.join(seed, 1);
    g.join(seed, 2);
    const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
    // Reversing one of them joins the two C1.
    CHECK((bezierDerivative(curves[0], 0.0) + bezierDerivative(curves[1], 0.0)).norm() < 1e-12);
    CHECK(bezierDerivative(curves[0], 0.0).x() > 0);
    for (const CurveSegment& c : curves)
      for (double x : {0.2, 0.6}) CHECK(std::abs(bezierPoint(c, x).y()) < 1e-15);
  }
  SECTION("an acute angle: they leave together along the bisector") {
    Graph g;
    const uint32_t seed = g.add(Vec3(0, 0, 0), n);
    g.add(Vec3(1, 0.4, 0), n);
    g.add(Vec3(1, -0.4, 0), n);
    g.join(seed, 1);
    g.join(seed, 2);
    const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
    const Vec3 d = bezierDerivative(curves[0], 0.0);
    CHECK((bezierDerivative(curves[1], 0.0) - d).norm() < 1e-12);
    CHECK((d.normalized() - Vec3(1, 0, 0)).norm() < 1e-12);
  }
  SECTION("two marches meeting head on at one node") {
    Graph g;
    g.add(Vec3(-1, 0, 0), n);
    g.add(Vec3(1, 0, 0), n);
    const uint32_t meet = g.add(Vec3(0, 0.1, 0), n);
    g.join(0, meet);
    g.join(1, meet);
    const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
    CHECK((bezierDerivative(curves[0], 1.0) + bezierDerivative(curves[1], 1.0)).norm() < 1e-12);
    CHECK((bezierDerivative(curves[0], 1.0).normalized() - Vec3(1, 0, 0)).norm() < 1e-12);
  }
}

TEST_CASE("a march turning straight back keeps a tangent and stays C1", "[smooth]") {
  const Vec3 n(0, 0, 1);
  Graph g;
  g.add(Vec3(0, 0, 0), n);
  g.add(Vec3(1, 0, 0), n);
  g.add(Vec3(0.5, 0, 0), n);
  g.join(0, 1);
  g.join(1, 2);
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  const Vec3 in = bezierDerivative(curves[0], 1.0);
  CHECK((bezierDerivative(curves[1], 0.0) - in).norm() < 1e-12);
  // The first segment's direction: the march overshoots and comes back.
  CHECK((in.normalized() - Vec3(1, 0, 0)).norm() < 1e-12);
  CHECK(in.norm() == Approx(3 * 0.5 / 3).epsilon(1e-12));  // h: a third of the shorter segment
}

TEST_CASE("zero-length segments are points and leave their neighbours alone", "[smooth]") {
  const Vec3 n(0, 0, 1);
  Graph g;
  g.add(Vec3(0, 0, 0), n);
  g.add(Vec3(1, 0, 0), n);
  g.add(Vec3(1, 0, 0), n);  // a step that went nowhere
  g.add(Vec3(2, 0, 0), n);
  g.join(0, 1);
  g.join(1, 2);
  g.join(2, 3);
  g.join(3, 3);
  const std::vector<CurveSegment> curves = smoothSegments(g.nodes, g.segments);
  for (int k = 0; k < 4; ++k) CHECK(control(curves[1], k) == Vec3(1, 0, 0));
  for (int k = 0; k < 4; ++k) CHECK(control(curves[3], k) == Vec3(2, 0, 0));
  // Nodes 1 and 2 each see one real segment: an end, handle a third of it.
  CHECK((control(curves[0], 2) - Vec3(2.0 / 3, 0, 0)).norm() < 1e-15);
  CHECK((control(curves[2], 1) - Vec3(4.0 / 3, 0, 0)).norm() < 1e-15);
}

TEST_CASE("a segment naming a missing node is refused", "[smooth]") {
  Graph g;
  g.add(Vec3(0, 0, 0), Vec3(0, 0, 1));
  g.add(Vec3(1, 0, 0), Vec3(0, 0, 1));
  g.join(0, 1);
  g.join(1, 5);
  CHECK_THROWS_WITH(smoothSegments(g.nodes, g.segments),
                    "smoothSegments: segment 1 joins nodes 1 and 5, but there are 2 nodes");
}

TEST_CASE("a seed growing three ways starts a perpendicular branch on the first one's side", "[smooth]") {
  // Three segments leave the seed (no growth passes through it) in its tangent plane: +x,
  // +y, -y. Sides start from the first segment's half-plane, a perpendicular one counted
  // on its side: (+1, +1, +1), sum (1, 0, 0). Single flips while the sum grows: +y flips
  // (its dot with the rest, (1, -1, 0), is -1), sum (1, -2, 0); then no flip lengthens it.
  // t = (1, -2, 0) / sqrt 5; the projections |t . away| are 1, 2, 2 over sqrt 5 (each
  // segment 1 long), their mean sqrt 5 / 3, so h = sqrt 5 / 9 and the inner control points
  // are side * h * t = side * (1, -2, 0) / 9.
  const Vec3 up(0, 0, 1);
  const std::vector<MarchNode> nodes = {
      {Vec3(0, 0, 0), up}, {Vec3(1, 0, 0), up}, {Vec3(0, 1, 0), up}, {Vec3(0, -1, 0), up}};
  const std::vector<MarchSegment> segments = {{0, 1}, {0, 2}, {0, 3}};
  const std::vector<CurveSegment> curves = smoothSegments(nodes, segments);
  REQUIRE(curves.size() == 3);
  CHECK((control(curves[0], 1) - Vec3(1, -2, 0) / 9).norm() < 1e-15);
  CHECK((control(curves[1], 1) - Vec3(-1, 2, 0) / 9).norm() < 1e-15);
  CHECK((control(curves[2], 1) - Vec3(1, -2, 0) / 9).norm() < 1e-15);
}

// The Marching rule's smoothness parameter (march_graph.h TerminalSmoothness), on a plane
// with normal +Z: p0 = 0, p1 = (1, 0, 0), p2 = p1 + (cos 30°, sin 30°, 0) — two unit steps,
// the second turned by 30°. Expectations by hand (smooth_curves.h's formulas).
TEST_CASE("C0 curves meet at the joint with each segment's own chord tangent, C1 ones share it", "[smooth]") {
  const double turn = M_PI / 6;
  const Vec3 d0(1, 0, 0), d1(std::cos(turn), std::sin(turn), 0);
  auto walk = [&](TerminalSmoothness first, TerminalSmoothness second) {
    Graph g;
    g.add(Vec3::Zero(), Vec3::UnitZ());
    g.add(d0, Vec3::UnitZ());
    g.add(d0 + d1, Vec3::UnitZ());
    g.segments.push_back({0, 1, first});
    g.segments.push_back({1, 2, second});
    return smoothSegments(g.nodes, g.segments);
  };
  // The angle between two vectors, exact near 0 (atan2 of |a x b| and a . b).
  auto angle = [](const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); };

  const auto c0 = walk(TerminalSmoothness::C0, TerminalSmoothness::C0);
  // b1 = a + (b - a) / 3, b2 = b - (b - a) / 3 on a plane: the chord at thirds.
  CHECK((control(c0[0], 1) - d0 / 3).norm() < 1e-14);
  CHECK((control(c0[0], 2) - 2 * d0 / 3).norm() < 1e-14);
  CHECK((control(c0[1], 1) - (d0 + d1 / 3)).norm() < 1e-14);
  CHECK((control(c0[1], 2) - (d0 + 2 * d1 / 3)).norm() < 1e-14);
  CHECK((bezierPoint(c0[0], 1.0) - bezierPoint(c0[1], 0.0)).norm() < 1e-9);  // position-continuous
  CHECK((bezierDerivative(c0[0], 1.0) - d0).norm() < 1e-12);                  // B' = 3 (c3 - c2) = d0
  CHECK((bezierDerivative(c0[1], 0.0) - d1).norm() < 1e-12);
  CHECK(angle(bezierDerivative(c0[0], 1.0), bezierDerivative(c0[1], 0.0)) == Approx(turn).margin(1e-9));

  const auto c1 = walk(TerminalSmoothness::C1, TerminalSmoothness::C1);
  // The joint's tangent bisects the turn, (cos 15°, sin 15°, 0), with the handle a third
  // of the mean projection cos 15°: both derivatives there are cos 15° (cos 15°, sin 15°, 0).
  const Vec3 bisector(std::cos(turn / 2), std::sin(turn / 2), 0);
  const Vec3 derivative = std::cos(turn / 2) * bisector;
  CHECK((bezierDerivative(c1[0], 1.0) - derivative).norm() < 1e-12);
  CHECK((bezierDerivative(c1[1], 0.0) - derivative).norm() < 1e-12);
  CHECK(angle(bezierDerivative(c1[0], 1.0), bezierDerivative(c1[1], 0.0)) == Approx(0).margin(1e-9));
  CHECK((control(c1[0], 1) - d0 / 3).norm() < 1e-14);  // the free ends: the segment's own direction

  // A C1 segment after a C0 one shares the joint with no other C1 segment: its own
  // direction, a third of its length.
  const auto mixed = walk(TerminalSmoothness::C0, TerminalSmoothness::C1);
  CHECK((control(mixed[0], 2) - 2 * d0 / 3).norm() < 1e-14);
  CHECK((control(mixed[1], 1) - (d0 + d1 / 3)).norm() < 1e-12);
}

TEST_CASE("C0 curves are tangent to the surface at their ends, discontinuous ones are the chord", "[smooth]") {
  // One unit segment along X whose start normal leans 30° towards +X:
  // n0 = (sin 30°, 0, cos 30°). C0: b1 = a + (I - n0 n0^T)(1, 0, 0) / 3
  // = (cos² 30°, 0, -sin 30° cos 30°) / 3 = (0.25, 0, -0.1443375672974064...).
  const double lean = M_PI / 6;
  Graph g;
  g.add(Vec3::Zero(), Vec3(std::sin(lean), 0, std::cos(lean)));
  g.add(Vec3(1, 0, 0), Vec3::UnitZ());
  g.segments.push_back({0, 1, TerminalSmoothness::C0});
  g.segments.push_back({0, 1, TerminalSmoothness::Discontinuous});
  const auto curves = smoothSegments(g.nodes, g.segments);
  CHECK((control(curves[0], 1) - Vec3(0.25, 0, -std::sqrt(3.0) / 12)).norm() < 1e-14);
  CHECK((control(curves[0], 2) - Vec3(2.0 / 3, 0, 0)).norm() < 1e-14);  // n1 = Z: the chord is tangent
  CHECK(std::abs((control(curves[0], 1) - control(curves[0], 0)).dot(normal0(curves[0]))) < 1e-14);
  CHECK((control(curves[1], 1) - Vec3(1.0 / 3, 0, 0)).norm() < 1e-14);
  CHECK((control(curves[1], 2) - Vec3(2.0 / 3, 0, 0)).norm() < 1e-14);
}
