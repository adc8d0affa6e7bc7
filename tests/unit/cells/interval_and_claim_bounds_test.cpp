// Two survivors of the cells mutation run (issue #51, docs/testing.md): intersecting
// lists of several intervals, and a claim that lies wholly outside its face's box.
#include "runtime/cells/feature_mesh.h"
#include "runtime/cells/occupancy.h"
#include "runtime/surface/procedural.h"

#include <catch2/catch.hpp>

using namespace fgsg::rt;
using namespace fgsg::rt::cells;

TEST_CASE("intersecting interval lists keeps every common piece", "[cells]") {
  // The merge advances the list whose current interval ends first; advancing the other
  // one skips [2, 3] here, which the single long interval also covers.
  const std::vector<Interval> two = {{0, 1}, {2, 3}}, one = {{0, 3}};
  for (const auto& out : {intersect(two, one), intersect(one, two), intersect(two, two)}) {
    REQUIRE(out.size() == 2);
    CHECK(out[0].lo == 0);
    CHECK(out[0].hi == 1);
    CHECK(out[1].lo == 2);
    CHECK(out[1].hi == 3);
  }
  const auto shifted = intersect({{0, 2}, {3, 5}}, {{1, 4}});
  REQUIRE(shifted.size() == 2);
  CHECK(shifted[0].lo == 1);
  CHECK(shifted[0].hi == 2);
  CHECK(shifted[1].lo == 3);
  CHECK(shifted[1].hi == 4);
}

TEST_CASE("a claim outside the face's box adds no break, one inside adds its two heights", "[cells]") {
  const surface::SurfaceMesh m = surface::plane(2, 2, 1);
  const FeatureMesh fm = buildFeatureMesh(m);
  REQUIRE(fm.faces.size() == 1);
  FaceOccupancy map(fm.faces[0], m);
  const Vec2 lo = map.lo(), hi = map.hi();
  REQUIRE(hi.y() - lo.y() == Approx(2).margin(1e-9));
  const double x0 = lo.x() + 0.5, x1 = lo.x() + 1;
  // Wholly above the face (y from hi + 1 to hi + 2), within its u range.
  map.claim({{x0, hi.y() + 1}, {x1, hi.y() + 1}, {x1, hi.y() + 2}, {x0, hi.y() + 2}});
  const auto outside = map.breaks(lo.y() - 5, hi.y() + 5);
  REQUIRE(outside.size() == 2);  // the face's own outline only
  CHECK(outside[0] == Approx(lo.y()).margin(1e-9));
  CHECK(outside[1] == Approx(hi.y()).margin(1e-9));
  // Inside the face, 0.5 to 1 above its bottom: both heights become breaks.
  map.claim({{x0, lo.y() + 0.5}, {x1, lo.y() + 0.5}, {x1, lo.y() + 1}, {x0, lo.y() + 1}});
  const auto inside = map.breaks(lo.y() - 5, hi.y() + 5);
  REQUIRE(inside.size() == 4);
  CHECK(inside[1] == Approx(lo.y() + 0.5).margin(1e-9));
  CHECK(inside[2] == Approx(lo.y() + 1).margin(1e-9));
}
