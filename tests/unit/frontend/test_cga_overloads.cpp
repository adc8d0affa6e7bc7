// CityEngine's rule overloading in the `.cga` dialect: rules of one name with different
// numbers of parameters are different rules, a call picks one by its argument count (here
// and through an import's alias), and misuse is a located error (file:line:col, the line
// and a caret). What both engines compute is the corpus's (tests/cga/corpus/186_rule_overloads).
#include "cga_compile_helpers.h"

#include <catch2/catch.hpp>

#include <string>

using namespace fgsg;

namespace {

using OverloadCompile = frontend::test::CgaCompiled;

// main.cga (`text`) beside lib.cga, whose Door has a rule without parameters and a
// stochastic one with three.
OverloadCompile compileWithDoorLibrary(const std::string& text) {
  const std::string dir = "/tmp/fgsg_cga_overloads_test";
  frontend::test::writeImportedFile(dir, "lib.cga",
                                    "Door --> extrude(1) Low.\n"
                                    "Door(w, h, d) --> 50% : extrude(h) High. else : s(w, 1, d) Flat.\n");
  return frontend::test::compileGrammarText(text, dir + "/main.cga");
}

int overloadParamCount(const ir::Module& m, const std::string& shownName) {
  const int index = m.findSymbol(shownName);
  return index < 0 ? -1 : int(m.symbols[size_t(index)].paramTypes.size());
}

}  // namespace

TEST_CASE("cga overloads: Door and Door(w, h, d) are two rules, case and stochastic ones too", "[cga][dialect]") {
  const auto c = frontend::test::compileGrammarText(
      "Lot --> Door Door(1, 2, 3) Door(4)\n"
      "Door --> extrude(3)\n"
      "Door(w, h, d) --> case w > 1 : s(w, h, d) X. else : Door\n"
      "Door(k) --> 30% : extrude(k) else : Door(k, k, k)\n");
  INFO(c.messages);
  REQUIRE(c.ok);
  // The fewest parameters keep the name; the others are shown with their count.
  CHECK(overloadParamCount(c.module, "Door") == 0);
  CHECK(overloadParamCount(c.module, "Door/1") == 1);
  CHECK(overloadParamCount(c.module, "Door/3") == 3);
  // Every overload's leaf is the written name's: instances are named Door.
  CHECK(c.module.findSymbol("Door.") >= 0);
  CHECK(c.module.findSymbol("Door/1.") < 0);
}

TEST_CASE("cga overloads: a call with a number of arguments no rule has lists theirs", "[cga][dialect]") {
  const auto c = frontend::test::compileGrammarText(
      "Lot --> Door(1, 2)\n"
      "Door --> extrude(3)\n"
      "Door(w, h, d) --> extrude(h)\n");
  CHECK_FALSE(c.ok);
  CHECK(c.says("test.cga:1:9: error[E019]: 'Door' takes 0 or 3 parameters, got 2\n"
               "Lot --> Door(1, 2)\n"
               "        ^~~~\n"));
  const auto bare = frontend::test::compileGrammarText(
      "Lot --> Door\n"
      "Door(w) --> extrude(w)\n"
      "Door(w, h) --> extrude(h)\n");
  CHECK_FALSE(bare.ok);
  CHECK(bare.says("test.cga:1:9: error[E019]: 'Door' takes 1 or 2 parameters\n"));
}

TEST_CASE("cga overloads: two rules of one name with the same number of parameters are an error", "[cga][dialect]") {
  const auto c = frontend::test::compileGrammarText(
      "Lot --> Door(1)\n"
      "Door(w) --> extrude(w)\n"
      "Door --> extrude(1)\n"
      "Door(h) --> extrude(2)\n");
  CHECK_FALSE(c.ok);
  CHECK(c.says("test.cga:4:1: error[E019]: 'Door' has a second rule with 1 parameters (the first is at line 2:1): "
               "rules of one name differ in their number of parameters\n"
               "Door(h) --> extrude(2)\n"
               "^~~~\n"));
}

TEST_CASE("cga overloads: an import's overloads are called through its alias", "[cga][dialect]") {
  const auto ok = compileWithDoorLibrary("import F : \"lib.cga\"\nLot --> F.Door F.Door(1, 2, 3)\n");
  INFO(ok.messages);
  REQUIRE(ok.ok);
  CHECK(overloadParamCount(ok.module, "F.Door") == 0);
  CHECK(overloadParamCount(ok.module, "F.Door/3") == 3);

  const auto wrong = compileWithDoorLibrary("import F : \"lib.cga\"\nLot --> F.Door(1, 2, 3) F.Door(1, 2)\n");
  CHECK_FALSE(wrong.ok);
  CHECK(wrong.says("main.cga:2:25: error[E019]: 'F.Door' takes 0 or 3 parameters, got 2\n"));
}

TEST_CASE("cga overloads: the start rule is the overload without parameters", "[cga][dialect]") {
  const auto c = frontend::test::compileGrammarText("Door --> extrude(3)\nDoor(h) --> extrude(h)\n", "test.cga", "Door");
  INFO(c.messages);
  CHECK(c.ok);
  const auto none = frontend::test::compileGrammarText("Door(w) --> extrude(w)\nDoor(w, h) --> extrude(h)\n",
                                                       "test.cga", "Door");
  CHECK_FALSE(none.ok);
  CHECK(none.says("error[E803]: --start-rule Door: the start rule 'Door' takes parameters: a start shape has none to give"));
}
