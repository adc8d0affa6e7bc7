// Many random marches: whatever the start, direction and length, a march ends on the
// surface, inside the atlas, in bounded work — and on a closed surface it always arrives.
#include "march_fixtures.h"

#include <tbb/parallel_for.h>

#include <random>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using namespace fgsg::rt::marching::testing;

namespace {

struct RandomMarch {
  MarchPoint from;
  double length;
  LengthUnit unit;
};

// Uniform faces, uniform points in them, uniform tangent directions; lengths uniform up
// to maxLength (3D) or the same in texels.
std::vector<RandomMarch> randomMarches(const MarchingSurface& s, int count, double maxLength, double texelsPerUnit,
                                       uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> face(0, int(s.mesh().faceCount()) - 1);
  std::uniform_real_distribution<double> unit01(0, 1), angle(0, 2 * kPi);
  std::vector<RandomMarch> out;
  for (int k = 0; k < count; ++k) {
    const int f = face(rng);
    double a = unit01(rng), b = unit01(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const Vec3 n = s.mesh().faceNormals[f];
    const Vec3 e = n.unitOrthogonal(), e2 = n.cross(e);
    const double phi = angle(rng);
    const surface::SurfacePoint p{f, Vec3(1 - a - b, a, b)};
    const LengthUnit unit = k % 2 ? LengthUnit::Image : LengthUnit::Surface;
    const double length = maxLength * unit01(rng) * (unit == LengthUnit::Image ? texelsPerUnit : 1);
    out.push_back({s.place(p, std::cos(phi) * e + std::sin(phi) * e2), length, unit});
  }
  return out;
}

struct Outcome {
  int arrived = 0, stopped = 0, worstPieces = 0, adjacencyJumps = 0;
};

// Runs the marches with every check that holds for any surface; `onBoundary` says
// whether a point is on the surface's own boundary.
template <class OnBoundary>
Outcome check(const MarchingSurface& s, const std::vector<RandomMarch>& marches, OnBoundary onBoundary) {
  const surface::SurfaceLocator locator(s.mesh());
  Outcome out;
  for (const RandomMarch& m : marches) {
    MarchPoint to;
    MarchTrace trace;
    const bool arrived = s.march(m.from, m.length, m.unit, to, &trace);
    INFO("from face " << m.from.at.face << " bary " << m.from.at.bary.transpose() << " dir "
                      << m.from.dir.transpose() << " length " << m.length
                      << (m.unit == LengthUnit::Image ? " texels" : ""));
    REQUIRE(consistent(s, to));
    double distance = 1;
    locator.closestPoint(s.position(to), &distance);
    REQUIRE(distance < 1e-9);
    if (arrived && m.unit == LengthUnit::Surface)
      REQUIRE(std::abs((s.position(to) - s.position(m.from)).norm() - m.length) <= 1e-9 * m.length);
    if (!arrived) REQUIRE(onBoundary(s.position(to)));
    ++(arrived ? out.arrived : out.stopped);
    out.worstPieces = std::max(out.worstPieces, trace.pieces);
    out.adjacencyJumps += trace.adjacencyJumps;
  }
  return out;
}

}  // namespace

TEST_CASE("100 000 random marches on the cube arrive, on the surface", "[marching][march][random]") {
  const auto s = prepared(chartedCube(8, 1024));
  const double texelsPerUnit = (1.0 / 3 - 8.0 / 1024) * 1024;
  const auto marches = randomMarches(*s, 100000, 0.8, texelsPerUnit, 2024);
  const Outcome o = check(*s, marches, [](const Vec3&) { return false; });  // closed: no boundary
  CHECK(o.arrived == 100000);
  CHECK(o.adjacencyJumps == 0);
  CHECK(o.worstPieces < 500);
}

TEST_CASE("100 000 random marches on the open cylinder arrive or stop at a rim", "[marching][march][random]") {
  const auto s = prepared(chartedCylinder());
  const double texelsPerUnit = (0.5 - 8.0 / 1024) * 1024 / 2;
  const auto marches = randomMarches(*s, 100000, 1.5, texelsPerUnit, 77);
  const Outcome o = check(*s, marches, [](const Vec3& p) { return std::abs(std::abs(p.z()) - 1) < 1e-12; });
  CHECK(o.arrived > 30000);
  CHECK(o.stopped > 10000);
  CHECK(o.adjacencyJumps == 0);
  CHECK(o.worstPieces < 2000);
}

TEST_CASE("marches from many threads at once give the answers of one thread", "[marching][march][random]") {
  const auto s = prepared(chartedCube(8, 512));
  const auto marches = randomMarches(*s, 20000, 1.0, 160, 5);
  std::vector<MarchPoint> serial(marches.size()), parallel(marches.size());
  std::vector<char> serialOk(marches.size()), parallelOk(marches.size());
  for (size_t i = 0; i < marches.size(); ++i)
    serialOk[i] = s->march(marches[i].from, marches[i].length, marches[i].unit, serial[i]);
  tbb::parallel_for(size_t(0), marches.size(), [&](size_t i) {
    parallelOk[i] = s->march(marches[i].from, marches[i].length, marches[i].unit, parallel[i]);
  });
  for (size_t i = 0; i < marches.size(); ++i) {
    REQUIRE(serialOk[i] == parallelOk[i]);
    REQUIRE(serial[i].at.face == parallel[i].at.face);
    REQUIRE(serial[i].at.bary == parallel[i].at.bary);
    REQUIRE(serial[i].dir == parallel[i].dir);
  }
}
