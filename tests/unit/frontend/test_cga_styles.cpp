// The `.cga` dialect's styles beyond attrs: rules, consts, functions and new attrs in a
// style, an import's styles list, and the located errors of misuse (file:line:col, the
// line and a caret). What both engines compute is the corpus's
// (tests/cga/corpus/155_style_rules*, 156_import_styles*, 157_import_all_styles*).
#include "cga_compile_helpers.h"

#include <catch2/catch.hpp>

#include <string>

using namespace fgsg;

namespace {

using StyledCompile = frontend::test::CgaCompiled;

// main.cga (`text`) beside lib.cga, a library with the styles Red and Tall (extends Red).
StyledCompile compileStyled(const std::string& text, const std::string& startRule = "") {
  const std::string dir = "/tmp/fgsg_cga_styles_test";
  frontend::test::writeImportedFile(dir, "lib.cga",
      "const tile = 2\n"
      "Mass --> extrude(5) T.\n"
      "style Red\n"
      "const tile = 4\n"
      "style Tall extends Red\n"
      "Mass --> extrude(8) T.\n");
  return frontend::test::compileGrammarText(text, dir + "/main.cga", startRule);
}

}  // namespace

TEST_CASE("cga styles: rules, consts, functions and new attrs in a style compile in every style", "[cga][dialect]") {
  const std::string text =
      "attr h = 10\n"
      "const n = 2\n"
      "w(k) = k * 2\n"
      "@StartRule\n"
      "Lot --> extrude(h) split(x) { ~w(n) : Tile }*\n"
      "Tile --> A.\n"
      "style Glass\n"
      "attr roof = 3\n"
      "const n = 4\n"
      "Tile --> extrude(roof) B.\n"
      "style Wide extends Glass\n"
      "w(k) = k * 5\n";
  for (const char* start : {"", "Default$Lot", "Glass$Lot", "Wide$Lot"}) {
    INFO(start);
    const StyledCompile c = compileStyled(text, start);
    CHECK(c.ok);
    CHECK(c.messages.empty());
  }
  // A style's own rule, attr or function is not the Default style's: used there, it is unknown.
  const StyledCompile own = compileStyled("@StartRule\nLot --> extrude(roof) X.\nstyle Glass\nattr roof = 3\n");
  CHECK_FALSE(own.ok);
  CHECK(own.says("main.cga:2:17: error"));
  CHECK(compileStyled("@StartRule\nLot --> extrude(roof) X.\nstyle Glass\nattr roof = 3\n", "Glass$Lot").ok);
  // The @StartRule stays with a rule a style redefines without the annotation.
  CHECK(compileStyled("@StartRule\nStart --> X.\nstyle Glass\nStart --> Y.\n", "Glass$").ok);
}

TEST_CASE("cga styles: cycles, unknown and twice-declared styles are located errors", "[cga][dialect]") {
  const StyledCompile cycle = compileStyled("@StartRule\nLot --> X.\nstyle A extends B\nstyle B extends A\n");
  CHECK_FALSE(cycle.ok);
  CHECK(cycle.says("main.cga:3:17: error[E803]: style cycle: A extends B extends A; a style's bases end at Default\n"
                   "style A extends B\n"
                   "                ^\n"));
  const StyledCompile self = compileStyled("@StartRule\nLot --> X.\nstyle A extends A\n");
  CHECK(self.says("main.cga:3:17: error[E803]: style cycle: A extends A; a style's bases end at Default"));
  // A base may come after the style that extends it.
  CHECK(compileStyled("@StartRule\nLot --> X.\nstyle A extends B\nstyle B\nLot --> Y.\n", "A$Lot").ok);
  const StyledCompile twice = compileStyled("@StartRule\nLot --> X.\nstyle A\nstyle A\n");
  CHECK(twice.says("main.cga:4:7: error[E803]: the style 'A' is declared twice\nstyle A\n      ^\n"));
  CHECK(twice.says("main.cga:3:7: note: 'A' is first declared here"));
  const StyledCompile unknown = compileStyled("@StartRule\nLot --> X.\nstyle Glass\n", "Glas$Lot");
  CHECK(unknown.says("main.cga:1:1: error[E803]: --start-rule Glas$Lot: this file has no style 'Glas' (its styles: "
                     "Default, Glass); did you mean 'Glass'?"));
  CHECK(compileStyled("@StartRule\nLot --> X.\nstyle Default extends Glass\n").says(
      "main.cga:3:1: error[E803]: the Default style extends no other style"));
}

TEST_CASE("cga import styles lists: the module's styles come here, misuse is located", "[cga][dialect]") {
  CHECK(compileStyled("import lib (Red, Tall) : \"lib.cga\"\n@StartRule\nLot --> lib.Mass\n").ok);
  // Tall is a style of this file through its import, with or without a list naming it.
  CHECK(compileStyled("import lib (Red, Tall) : \"lib.cga\"\n@StartRule\nLot --> lib.Mass\n", "Tall$Lot").ok);
  CHECK(compileStyled("import lib : \"lib.cga\"\n@StartRule\nLot --> lib.Mass\n", "Tall$Lot").ok);
  // With an attr list after the path as well.
  CHECK(compileStyled("import lib (Red) : \"lib.cga\" ()\n@StartRule\nLot --> lib.Mass\n").ok);
  const StyledCompile left = compileStyled("import lib (Red) : \"lib.cga\"\n@StartRule\nLot --> lib.Mass\n", "Tall$Lot");
  CHECK_FALSE(left.ok);
  CHECK(left.says("main.cga:1:1: error[E803]: --start-rule Tall$...: neither this file nor its imports have a style "
                  "'Tall' (their styles: Default, Red)"));
  const StyledCompile missing = compileStyled("import lib (Red, Tal) : \"lib.cga\"\n@StartRule\nLot --> lib.Mass\n");
  CHECK_FALSE(missing.ok);
  CHECK(missing.says("main.cga:1:18: error[E803]: the module 'lib.cga' has no style 'Tal' (its styles: Default, Red, "
                     "Tall); did you mean 'Tall'?\n"
                     "import lib (Red, Tal) : \"lib.cga\"\n"
                     "                 ^~~\n"));
}

TEST_CASE("cga styles: a style that redefines one overload of a rule keeps Default's others", "[cga][dialect]") {
  const std::string text =
      "@StartRule\n"
      "Lot --> split(x) { 10 : Door | 10 : Door(4) }\n"
      "Door --> extrude(1) Low.\n"
      "Door(h) --> extrude(h) High.\n"
      "style Red\n"
      "Door(h) --> extrude(h*2) RedHigh.\n";
  const StyledCompile red = compileStyled(text, "Red$Lot");
  INFO(red.messages);
  CHECK(red.ok);
  CHECK_FALSE(red.says("error"));
  CHECK(red.module.findSymbol("Low") >= 0);      // Default's Door
  CHECK(red.module.findSymbol("RedHigh") >= 0);  // Red's Door(h)
  CHECK(red.module.findSymbol("High") < 0);      // Default's Door(h), overridden
  const StyledCompile plain = compileStyled(text);
  CHECK(plain.ok);
  CHECK(plain.module.findSymbol("High") >= 0);
  CHECK(plain.module.findSymbol("RedHigh") < 0);
}
