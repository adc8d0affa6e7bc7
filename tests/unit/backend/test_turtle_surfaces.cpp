// ABOP's predefined surfaces `~name(s)`: an asset placed at the turtle, standing on it
// along the heading and centred on it, without moving the turtle.
#include "derive_helpers.h"

#include <catch2/catch.hpp>

using namespace fgsg;
using test::unitPoint;

namespace {

const rt::Instance& only(const rt::DeriveResult& r, const std::string& asset) {
  REQUIRE(r.ok);
  REQUIRE(test::countAsset(r, asset) == 1);
  for (const auto& inst : r.instances.instances)
    if (r.instances.assets[inst.asset] == asset) return inst;
  throw std::logic_error("unreachable");
}

bool near(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).norm() < 1e-12; }

}  // namespace

TEST_CASE("a predefined surface stands on the turtle along its heading, centred on it", "[lsystem][turtle]") {
  // After F + (heading -X), a 0.2 x 0.4 x 0.1 cube: its base centre at the turtle, its
  // Y along the heading.
  const auto r = test::deriveText("derive parallel 0;\naxiom: F + ~cube(0.2, 0.4, 0.1) F;");
  const rt::Instance& cube = only(r, "cube");
  CHECK(near(unitPoint(cube, 0.5, 0, 0.5), {0, 1, 0}));
  CHECK(near(unitPoint(cube, 0.5, 1, 0.5), {-0.4, 1, 0}));
  CHECK(near(unitPoint(cube, 1, 0, 0.5) - unitPoint(cube, 0, 0, 0.5), {0, 0.2, 0}));
  CHECK(near(unitPoint(cube, 0.5, 0, 1) - unitPoint(cube, 0.5, 0, 0), {0, 0, 0.1}));
  // The turtle did not move: the second segment starts where the first ended.
  CHECK(near(unitPoint(r.instances.instances.back(), 0.5, 0, 0.5), {0, 1, 0}));
}

TEST_CASE("a flat surface lies in the turtle's plane, one size scales every axis, none is 1", "[lsystem][turtle]") {
  // leaf lies at z = 0 of its box: its plane passes through the turtle.
  const auto leaf = test::deriveText("derive parallel 0;\naxiom: f ~leaf(0.5);");
  const rt::Instance& l = only(leaf, "leaf");
  CHECK(near(unitPoint(l, 0, 0, 0), {-0.25, 1, 0}));
  CHECK(near(unitPoint(l, 1, 1, 0), {0.25, 1.5, 0}));
  const auto sphere = test::deriveText("derive parallel 0;\naxiom: ~sphere;");
  const rt::Instance& s = only(sphere, "sphere");
  CHECK(near(unitPoint(s, 0, 0, 0), {-0.5, 0, -0.5}));
  CHECK(near(unitPoint(s, 1, 1, 1), {0.5, 1, 0.5}));
}

TEST_CASE("predefined surfaces grow in parallel and sequential derivations, from files too", "[lsystem][turtle]") {
  // Each step adds a leaf; the instance is the rewriting module's, with its parameters.
  const auto p = test::deriveText("derive parallel 2;\naxiom: A(1);\nA(k) ~> F ~\"Ellipse1.obj\"(k) A(k + 1);");
  REQUIRE(p.ok);
  CHECK(test::countAsset(p, "Ellipse1.obj") == 2);
  const auto s = test::deriveText("Lot ~> F ~disc(2) F;");
  const rt::Instance& disc = only(s, "disc");
  CHECK(near(unitPoint(disc, 0.5, 0.5, 0), {0, 2, 0}));
}

TEST_CASE("a predefined surface with two sizes is E016, an unknown one R003", "[lsystem][turtle]") {
  CHECK_THROWS_WITH(test::compileText("axiom: ~leaf(1, 2);"), Catch::Contains("E016"));
  const auto r = test::deriveText("derive parallel 0;\naxiom: ~nowhere;");
  REQUIRE_FALSE(r.ok);
  CHECK(r.messages[0].code == "R003");
}
