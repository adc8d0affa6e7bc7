// ABOP's colour index ' (the turtle's colour from a palette, saved by [ ]).
#include "derive_helpers.h"

#include <catch2/catch.hpp>

using namespace fgsg;

namespace {

std::vector<std::array<float, 3>> colours(const rt::DeriveResult& r) {
  REQUIRE(r.ok);
  std::vector<std::array<float, 3>> out;
  for (const auto& inst : r.instances.instances) out.push_back(inst.color);
  return out;
}

const std::array<float, 3> kBark{0.45f, 0.33f, 0.2f}, kRed{1, 0, 0}, kGreen{0, 1, 0};

}  // namespace

TEST_CASE("the colour index steps through turtle colors, picks one by number, and brackets restore it",
          "[lsystem][turtle]") {
  const auto r = test::deriveText(
      "derive parallel 0;\nturtle colors \"#ff0000 #00ff00\";\naxiom: F ' F [ ' F ] F '(0) F '(5) F;");
  CHECK(colours(r) == std::vector<std::array<float, 3>>{kBark, kRed, kGreen, kRed, kBark, kRed});
}

TEST_CASE("the colour index works in rewritten strings and in sequential successors alike", "[lsystem][turtle]") {
  // Parallel: each step adds a ' before the new segment.
  const auto p = test::deriveText("derive parallel 2;\nturtle colors \"#ff0000 #00ff00\";\naxiom: A;\nA ~> F ' A;");
  CHECK(colours(p) == std::vector<std::array<float, 3>>{kBark, kRed});
  // Sequential: the colour is the successor's.
  const auto s = test::deriveText("turtle colors \"#00ff00\";\nLot ~> ' F;");
  CHECK(colours(s) == std::vector<std::array<float, 3>>{kGreen});
}

TEST_CASE("a colour index that is no whole number from 0 is R027", "[lsystem][turtle]") {
  const auto r = test::deriveText("derive parallel 0;\naxiom: '(-1) F;");
  REQUIRE_FALSE(r.ok);
  CHECK(r.messages[0].code == "R027");
}
