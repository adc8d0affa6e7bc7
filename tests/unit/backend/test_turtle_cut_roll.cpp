// ABOP's % (cut the rest of a branch, §1.10) and $ (roll the left vector level, Fig. 2.6).
#include "derive_helpers.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

using namespace fgsg;
using Catch::Matchers::Contains;

namespace {

size_t segments(const rt::DeriveResult& r) {
  REQUIRE(r.ok);
  return test::countAsset(r, "cylinder");
}

}  // namespace

TEST_CASE("% cuts the rest of its branch, or of the string, after each step", "[lsystem][turtle]") {
  // After one step: F [ + F % F F ] F % F  becomes  F [ + F ] F.
  CHECK(segments(test::deriveText("derive parallel 1;\naxiom: A;\nA ~> F [ + F % F F ] F % F;")) == 3);
  // Nested branches after the cut go too; the branch's own ] stays, so what follows it draws.
  CHECK(segments(test::deriveText("derive parallel 1;\naxiom: A;\nA ~> [ F % [ F ] F ] F;")) == 2);
  // Cut in the axiom as well, and a module the cut removed is never rewritten.
  CHECK(segments(test::deriveText("derive parallel 2;\naxiom: F % A;\nA ~> F F A;")) == 1);
  // ABOP §1.10: a bud that becomes a cut sheds its branch at the next step.
  CHECK(segments(test::deriveText("derive parallel 2;\naxiom: F [ + B F F ] F;\nB ~> %;")) == 2);
}

TEST_CASE("% in a sequential derivation is a located error", "[lsystem][turtle]") {
  const auto r = test::deriveText("Lot ~> F %;");
  REQUIRE_FALSE(r.ok);
  CHECK(r.messages[0].code == "R009");
  CHECK_THAT(r.messages[0].message, Contains("parallel"));
}

TEST_CASE("$ rolls about the heading until the left vector is level", "[lsystem][turtle]") {
  const auto r = test::deriveText("derive parallel 0;\naxiom: /(37) &(25) \\(12) $ F;");
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 1);
  const Eigen::Matrix4d t = test::transformOf(r.instances.instances[0]);
  // The turtle's left L is the scope's -X (docs/language.md, the turtle).
  const Eigen::Vector3d left = -t.block<3, 1>(0, 0).normalized(), heading = t.block<3, 1>(0, 1).normalized();
  CHECK(left.y() == Approx(0).margin(1e-12));                 // level
  // ABOP's L = V x H / |V x H|, whichever way the turtle was rolled before.
  CHECK((left - Eigen::Vector3d::UnitY().cross(heading).normalized()).norm() < 1e-12);
  // U = H x L, so U points up (L-Py's and lpfg's RollToVert: "U closest to up").
  CHECK((t.block<3, 1>(0, 2).normalized() - heading.cross(left)).norm() < 1e-12);
  CHECK(t.block<3, 1>(0, 2).y() > 0);
  const auto over = test::deriveText("derive parallel 0;\naxiom: /(200) &(25) $ F;");
  const Eigen::Matrix4d o = test::transformOf(over.instances.instances[0]);
  const Eigen::Vector3d overHeading = o.block<3, 1>(0, 1).normalized();
  CHECK((-o.block<3, 1>(0, 0).normalized() - Eigen::Vector3d::UnitY().cross(overHeading).normalized()).norm() < 1e-9);
  CHECK(left.dot(heading) == Approx(0).margin(1e-12));        // still square to the heading
  // The heading itself is unchanged by the roll: &(25) tilted it 25 degrees from +Y.
  CHECK(heading.y() == Approx(std::cos(25 * 3.14159265358979323846 / 180)).epsilon(1e-12));
  // Heading straight up, no direction is level: the turtle stays as it was.
  const auto up = test::deriveText("derive parallel 0;\naxiom: /(30) $ F;");
  const Eigen::Matrix4d u = test::transformOf(up.instances.instances[0]);
  CHECK(u.block<3, 1>(0, 0).normalized().y() == Approx(0).margin(1e-12));
}
