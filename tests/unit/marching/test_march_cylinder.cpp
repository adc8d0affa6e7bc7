// Marching on an open cylinder cut into four unrolled charts: seams along the axis, the
// surface's own boundary at both rims.
#include "march_fixtures.h"

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using namespace fgsg::rt::marching::testing;

namespace {

constexpr int kSegments = 48;
// Texels per unit of length on chartedCylinder(1, 2, 48, 24, 4, 1024, 4): the height 2
// is the charts' longer side, fitted into half the atlas less the gutters.
constexpr double kTexelsPerUnit = (0.5 - 8.0 / 1024) * 1024 / 2;
const double kChord = 2 * std::sin(kPi / kSegments);

}  // namespace

TEST_CASE("a march round the cylinder comes back to its start through four seams", "[marching][march][cylinder]") {
  const auto s = prepared(chartedCylinder());
  const Vec3 start(std::cos(0.3), std::sin(0.3), 0.37);
  const Vec3 around(-std::sin(0.3), std::cos(0.3), 0);
  const MarchPoint from = placeAt(*s, start, around);
  MarchPoint back;
  MarchTrace trace;
  REQUIRE(s->march(from, kSegments * kChord * kTexelsPerUnit, LengthUnit::Image, back, &trace));
  CHECK(trace.pointerJumps == 4);
  CHECK(trace.adjacencyJumps == 0);
  CHECK((s->position(back) - s->position(from)).norm() < 1e-9);
  CHECK((s->direction(back) - s->direction(from)).norm() < 1e-9);
}

TEST_CASE("a march up the cylinder stops at the rim", "[marching][march][cylinder]") {
  const auto s = prepared(chartedCylinder());
  for (double slope : {90.0, 30.0, -70.0}) {
    INFO("slope " << slope);
    const double a = slope * kPi / 180;
    // Start on a seam's far side so that the march crosses seams on its way.
    const Vec3 start(std::cos(1.5), std::sin(1.5), 0.2);
    const Vec3 around(-std::sin(1.5), std::cos(1.5), 0);
    const Vec3 dir = std::cos(a) * around + std::sin(a) * Vec3::UnitZ();
    for (LengthUnit unit : {LengthUnit::Surface, LengthUnit::Image}) {
      MarchPoint to;
      MarchTrace trace;
      CHECK_FALSE(s->march(placeAt(*s, start, dir), 1e4, unit, to, &trace));
      CHECK(consistent(*s, to));
      CHECK(std::abs(s->position(to).z()) == Approx(1.0).epsilon(1e-12));
      CHECK(std::signbit(s->position(to).z()) == std::signbit(dir.z()));
      // Unrolled, the path is straight: its length around the axis is the rise over
      // the tangent of the slope.
      const double rise = std::abs(s->position(to).z() - start.z());
      const double run = rise / std::tan(std::abs(a));
      const double along = s->direction(to).dot(Vec3::UnitZ());
      CHECK(along == Approx(std::sin(a)).margin(1e-9));
      // The start lies half a segment before a seam (segment 11.46 of the 12 of chart
      // 0): the slanted paths cross it, then run less than the next chart's width.
      CHECK(trace.pointerJumps == (slope == 90.0 ? 0 : 1));
      CHECK(run < 12 * kChord);
    }
  }
}

TEST_CASE("a chart cut open along a seam of its own is crossed through its own pointers",
          "[marching][march][cylinder]") {
  // The whole cylinder unrolled as one chart: its two cut edges lie a chart's width apart
  // in the image, and their pointers lead from one to the other.
  const auto s = prepared(chartedCylinder(1, 2, kSegments, 24, 1));
  const double texelsPerUnit = (0.5 - 8.0 / 1024) * 1024 / (kSegments * kChord);
  const Vec3 start(std::cos(0.3), std::sin(0.3), -0.41);
  const Vec3 around(-std::sin(0.3), std::cos(0.3), 0);
  const MarchPoint from = placeAt(*s, start, around);
  MarchPoint back;
  MarchTrace trace;
  REQUIRE(s->march(from, kSegments * kChord * texelsPerUnit, LengthUnit::Image, back, &trace));
  CHECK(trace.pointerJumps == 1);
  CHECK(trace.adjacencyJumps == 0);
  CHECK((s->position(back) - s->position(from)).norm() < 1e-9);
  CHECK((s->direction(back) - s->direction(from)).norm() < 1e-9);
}
