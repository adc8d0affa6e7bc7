// Each kind of segment `F` draws is centred on the turtle's path (docs/language.md, the
// turtle): a ribbon across its X, a cylinder across X and Z, a line on the path itself.
// The ribbon's offset was a survivor of the mutation run (issue #51).
#include "derive_helpers.h"

#include <catch2/catch.hpp>

#include <deque>

using namespace fgsg;
using test::unitPoint;

namespace {

const rt::Instance& firstSegment(const std::string& segments) {
  static std::deque<rt::DeriveResult> kept;  // the instances outlive the call (a deque never moves them)
  kept.push_back(test::deriveText("turtle width 0.4 segments \"" + segments +
                                  "\";\nderive parallel 0;\naxiom: F;"));
  const rt::DeriveResult& r = kept.back();
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 1);
  return r.instances.instances.front();
}

bool near(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).norm() < 1e-12; }

}  // namespace

TEST_CASE("segments are centred on the turtle's path whatever their kind", "[lsystem][turtle]") {
  // The turtle starts at the origin heading +Y with X to its side; step 1, width 0.4.
  const rt::Instance& ribbon = firstSegment("ribbons");
  CHECK(near(unitPoint(ribbon, 0, 0, 0), {-0.2, 0, 0}));
  CHECK(near(unitPoint(ribbon, 1, 1, 0), {0.2, 1, 0}));
  const rt::Instance& cylinder = firstSegment("cylinders");
  CHECK(near(unitPoint(cylinder, 0, 0, 0), {-0.2, 0, -0.2}));
  CHECK(near(unitPoint(cylinder, 1, 1, 1), {0.2, 1, 0.2}));
  const rt::Instance& line = firstSegment("lines");
  CHECK(near(unitPoint(line, 0, 0, 0), {0, 0, 0}));
  CHECK(near(unitPoint(line, 0, 1, 0), {0, 1, 0}));
}
