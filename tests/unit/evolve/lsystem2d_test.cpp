// 2D L-systems (Chan & Hui 2013 §3.1.2, Figs. 2-3): the string form, its errors, and
// generations with exact arrays.
#include "runtime/evolve/lsystem2d.h"

#include <catch2/catch.hpp>

#include <string>

using namespace fgsg::rt::evolve;

namespace {

std::string syntaxError(const std::string& text, const std::string& letters, size_t* column = nullptr) {
  try {
    parseLSystem(text, letters);
  } catch (const LSystemSyntaxError& e) {
    if (column) *column = e.column;
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("Fig. 2: {ABAA.ABBA.A} grows 2^g x 2^g, with the exact arrays", "[evolve][lsystem]") {
  const LSystem2D ls = parseLSystem("{ABAA.ABBA.A}");
  REQUIRE(ls.rules.size() == 2);
  CHECK(ls.ruleSide() == 2);
  CHECK(ls.axiom.side == 1);
  CHECK(formatLSystem(ls, "AB") == "{ABAA.ABBA.A}");
  for (int g = 0; g <= 6; ++g) {
    const AlleleGrid p = expand(ls, g);
    CHECK(p.side == (1 << g));
    CHECK(expandedSide(ls, g) == (1 << g));
  }
  CHECK(formatGrid(expand(ls, 0), "AB") == "A");
  CHECK(formatGrid(expand(ls, 1), "AB") == "ABAA");
  // Generation 2 by hand: A -> AB/AA, B -> AB/BA.
  //   AB AB
  //   AA BA
  //   AB AB
  //   AA AA
  CHECK(formatGrid(expand(ls, 2), "AB") == "ABAB" "AABA" "ABAB" "AAAA");
  // Generation 3: every cell of generation 2 replaced by its rule's 2x2 array.
  const AlleleGrid g2 = expand(ls, 2), g3 = expand(ls, 3);
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c) CHECK(g3.at(r, c) == ls.rules[g2.at(r / 2, c / 2).symbol].at(r % 2, c % 2));

  // The §3.1.2 example with a 2x2 axiom: sides 2 x 2^g.
  const LSystem2D ls2 = parseLSystem("{ABAA.ABBA.ABAA}");
  CHECK(expand(ls2, 3).side == 16);
  CHECK(formatGrid(expand(ls2, 1), "AB") == "ABAB" "AABA" "ABAB" "AAAA");
}

TEST_CASE("a rotated allele rewrites to its rule turned as a picture", "[evolve][lsystem]") {
  // Rule A -> AB/AA turned a quarter counter-clockwise: the top-right B moves to the
  // top-left, every allele gains 90 degrees.
  const LSystem2D ls = parseLSystem("{ABAA.ABBA.A90}");
  CHECK(ls.axiom.at(0, 0) == Allele{0, 1});
  CHECK(formatGrid(expand(ls, 1), "AB") == "B90A90" "A90A90");
  // Generation 2 by hand: B90 -> B90 A90 / A90 B90, A90 -> B90 A90 / A90 A90.
  CHECK(formatGrid(expand(ls, 2), "AB") == "B90A90B90A90" "A90B90A90A90" "B90A90B90A90" "A90A90A90A90");
  // Generation g of A90 is generation g of A turned.
  const LSystem2D upright = parseLSystem("{ABAA.ABBA.A}");
  for (int g = 0; g <= 4; ++g) CHECK(expand(ls, g) == turnGrid(expand(upright, g), 1));
  // Rotated alleles inside rules (Fig. 3): A -> A B90 / A270 A180 expands consistently.
  const LSystem2D fig3 = parseLSystem("{AB90A270A180.BA180A90B.A180}");
  const AlleleGrid g3 = expand(fig3, 3);
  CHECK(g3.side == 8);
  CHECK(g3 == turnGrid(expand(parseLSystem("{AB90A270A180.BA180A90B.A}"), 3), 2));
  // Four quarter turns are the identity.
  CHECK(turnGrid(turnGrid(g3, 3), 1) == g3);
}

TEST_CASE("string form: orientations, spaces, round trip", "[evolve][lsystem]") {
  const LSystem2D ls = parseLSystem(" { A90 B180 A_270 B0 . B A270 A A . A } ", "AB");
  CHECK(ls.rules[0].at(0, 0) == Allele{0, 1});
  CHECK(ls.rules[0].at(0, 1) == Allele{1, 2});
  CHECK(ls.rules[0].at(1, 0) == Allele{0, 3});
  CHECK(ls.rules[0].at(1, 1) == Allele{1, 0});
  CHECK(formatLSystem(ls, "AB") == "{A90B180A270B.BA270AA.A}");
  CHECK(parseLSystem(formatLSystem(ls, "AB"), "AB") == ls);
  // Braces are optional; other letters from the tile set.
  const LSystem2D xy = parseLSystem("X.Y.XYYX", "XY");
  CHECK(formatLSystem(xy, "XY") == "{X.Y.XYYX}");
  CHECK(xy.length() == 6);
  CHECK(xy.allele(5) == Allele{0, 0});
  CHECK_THROWS_AS(xy.allele(6), std::out_of_range);
}

TEST_CASE("string form errors say where and what", "[evolve][lsystem]") {
  size_t column = 0;
  CHECK(syntaxError("{ABAA.ABCA.A}", "AB", &column) == "column 9: unknown symbol 'C' (symbols: A, B)");
  CHECK(column == 9);
  CHECK(syntaxError("{ABA.ABBA.A}", "AB") == "column 2: part 1 has 3 alleles, not a square k x k array");
  CHECK(syntaxError("{ABAA.ABBA}", "AB") ==
        "column 12: expected 3 parts (2 rules, for A, B, then the axiom), got 2");
  CHECK(syntaxError("{ABAA.ABBA.A.A}", "AB") ==
        "column 14: expected 3 parts (2 rules, for A, B, then the axiom), got 4");
  CHECK(syntaxError("{A45BAA.ABBA.A}", "AB") == "column 3: orientation 45 of 'A' is not 0, 90, 180 or 270");
  CHECK(syntaxError("{A900BAA.ABBA.A}", "AB") == "column 3: orientation 900 of 'A' is not 0, 90, 180 or 270");
  CHECK(syntaxError("{ABAA.ABBA.A", "AB") == "column 1: '{' is not closed by '}'");
  CHECK(syntaxError("{ABAA..A}", "AB") == "column 7: part 2 is empty (two dots, or a dot first)");
  CHECK(syntaxError("{ABAA.A.A}", "AB") == "column 7: rule 2 (B) is 1x1 but rule 1 is 2x2: all rules have one size");
  CHECK(syntaxError("{90AB}", "AB") == "column 2: an orientation must follow a symbol letter");
  CHECK(syntaxError("{ABAA.ABBA.A} x", "AB") == "column 15: unexpected text after the L-system");
  CHECK(syntaxError("{AB+A.ABBA.A}", "AB") ==
        "column 4: unexpected character '+' (expected a symbol letter, '.' or '}')");
  CHECK(syntaxError("ABAA.ABBA.A}", "AB") == "column 12: '}' without an opening '{'");
  CHECK(syntaxError("", "AB") == "column 1: empty L-system");
  CHECK_THROWS_AS(parseLSystem("{ABAA}"), LSystemSyntaxError);  // no dot: no rules

  // expand()'s own checks.
  const LSystem2D ls = parseLSystem("{ABAA.ABBA.A}");
  CHECK_THROWS_AS(expand(ls, -1), std::invalid_argument);
  CHECK_THROWS_AS(expand(ls, 40), std::length_error);
  CHECK_THROWS_AS(expand(ls, 12, 1000), std::length_error);
  LSystem2D broken = ls;
  broken.axiom.at(0, 0).symbol = 2;
  CHECK_THROWS_AS(expand(broken, 1), std::invalid_argument);
}
