// ABOP's contexts in a sequential derivation: matched generation by generation in the
// string of shapes, whatever the derivation order.
#include "derive_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

using namespace fgsg;

namespace {

// Each placed asset with the origin of its instance (x, y), rounded to a grid of 0.5, sorted.
std::vector<std::pair<std::string, std::pair<double, double>>> placed(const rt::DeriveResult& r) {
  REQUIRE(r.ok);
  std::vector<std::pair<std::string, std::pair<double, double>>> out;
  for (const auto& inst : r.instances.instances) {
    const Eigen::Vector3d c = test::unitPoint(inst, 0, 0, 0);
    out.push_back({r.instances.assets[inst.asset], {std::round(c.x() * 2) / 2, std::round(c.y() * 2) / 2}});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A signal B moving right one shape per generation (ABOP §1.8): each generation draws a
// row one unit up, a sphere where B stands.
const char* const kSignal =
    "axiom: B(0) A(1) A(2) A(3) A(4);\n"
    "B(i) < A(j) ~> T(0, 1, 0) [ T(j, 0, 0) S(0.5, 0.5, 0.5) I(\"cube\") ] B(j);\n"
    "A(j) ~> T(0, 1, 0) [ T(j, 0, 0) S(0.5, 0.5, 0.5) I(\"cube\") ] A(j);\n"
    "B(i) ~> T(0, 1, 0) [ T(i, 0, 0) S(0.5, 0.5, 0.5) I(\"sphere\") ] A(i);\n";

}  // namespace

TEST_CASE("a context moves a signal along a sequential string, one generation a step", "[context]") {
  const auto spheres = [](const rt::DeriveResult& r) {
    std::vector<std::pair<double, double>> at;
    for (const auto& [asset, where] : placed(r))
      if (asset == "sphere") at.push_back(where);
    return at;
  };
  const auto breadth = test::deriveText(std::string("derive breadthfirst 4;\n") + kSignal);
  CHECK(spheres(breadth) == std::vector<std::pair<double, double>>{{0, 1}, {1, 2}, {2, 3}, {3, 4}});
  CHECK(placed(breadth).size() == 20);
  // Depth-first derives in another order and sees the same generations.
  const auto depth = test::deriveText(std::string("derive depthfirst 4;\n") + kSignal);
  CHECK(placed(depth) == placed(breadth));
}

TEST_CASE("sequential contexts see neighbours as written, over split parts", "[context]") {
  // The window left of a door gets a disc, the one right of a door a sphere; the first
  // door is derived before the windows after it and is still their neighbour.
  const auto r = test::deriveText(
      "Facade ~> S(5, 1, 1) Subdiv(\"X\", 1r, 1r, 1r, 1r, 1r){ Win | Door | Win | Win | Door };\n"
      "Door < Win ~> I(\"sphere\");\nWin > Door ~> I(\"disc\");\nWin ~> I(\"quad\");\nDoor ~> I(\"cube\");\n");
  std::vector<std::pair<double, std::string>> row;
  for (const auto& [asset, where] : placed(r)) row.push_back({where.first, asset});
  std::sort(row.begin(), row.end());
  std::vector<std::string> assets;
  for (const auto& [x, asset] : row) assets.push_back(asset);
  CHECK(assets == std::vector<std::string>{"disc", "cube", "sphere", "disc", "cube"});
}

TEST_CASE("sequential contexts skip branches, step over ignored symbols and bind parameters", "[context]") {
  // B's left neighbour is A(7) past the branch [ C ] and the ignored K; the sphere is
  // placed at x = 7, from the context parameter.
  const auto r = test::deriveText(
      "#ignore: K;\naxiom: A(7) [ C ] K B;\nA(k) < B ~> T(k, 0, 0) I(\"sphere\");\nB ~> I(\"cube\");\n"
      "A(k) ~> I(\"none\");\nC ~> I(\"none\");\nK ~> I(\"none\");\n");
  const auto p = placed(r);
  REQUIRE(p.size() == 1);
  CHECK(p[0].first == "sphere");
  CHECK(p[0].second.first == 7);
  // Right context entering a branch: A > [ C ] matches, A > C does not.
  const auto right = test::deriveText("axiom: A [ C ];\nA > [ C ] ~> I(\"sphere\");\nA ~> I(\"cube\");\n");
  CHECK(placed(right)[0].first == "sphere");
  const auto no = test::deriveText("axiom: A [ C ];\nA > C ~> I(\"sphere\");\nA ~> I(\"cube\");\n");
  CHECK(placed(no)[0].first == "cube");
}
