// The `.cga` dialect's calls of an imported file's functions (`F.windowWidth(3)`,
// `F.floorCount`), its initialShape attributes and its styles: what compiles, and the
// located errors of misuse. The values both engines compute are the corpus's
// (tests/cga/corpus/150_*, 151_*, 152_*).
#include "cga_compile_helpers.h"

#include <catch2/catch.hpp>

#include <string>

using namespace fgsg;

namespace {

using ImportedFunctionsCompiled = frontend::test::CgaCompiled;

ImportedFunctionsCompiled compileImporting(const std::string& text, const std::string& startRule = "") {
  const std::string dir = "/tmp/fgsg_cga_imported_functions_test";
  frontend::test::writeImportedFile(dir, "lib.cga",
      "attr floorHeight = 3\n"
      "const margin = 1\n"
      "windowWidth(n) = n * 0.5 + margin\n"
      "height = 2 * floorHeight\n"
      "broken(x) = x + nosuch\n"
      "sumTwice(x) = x + x\n");
  return frontend::test::compileGrammarText(text, dir + "/main.cga", startRule);
}

bool says(const ImportedFunctionsCompiled& c, const std::string& text) { return c.says(text); }

}  // namespace

TEST_CASE("cga imported functions: calls compile, misuse is located at the call", "[cga][dialect]") {
  const std::string head = "import F : \"lib.cga\"\nF.floorHeight = 4\n@StartRule\nLot --> ";
  const auto ok = compileImporting(head + "extrude(F.height) s(F.windowWidth(2), '1, '1) X.\n");
  INFO(ok.messages);
  CHECK(ok.ok);
  // A function of the importer that calls an imported one.
  CHECK(compileImporting("import F : \"lib.cga\"\ntwice(k) = 2 * F.windowWidth(k)\n@StartRule\nLot --> "
                         "extrude(twice(1)) X.\n")
            .ok);

  const auto unknown = compileImporting(head + "extrude(F.windowWith(2)) X.\n");
  CHECK_FALSE(unknown.ok);
  CHECK(says(unknown, "main.cga:4:17: error[E062]: the module 'lib.cga' has no function 'windowWith'; did you "
                      "mean 'F.windowWidth'?"));
  const auto arity = compileImporting(head + "extrude(F.windowWidth(1, 2)) X.\n");
  CHECK_FALSE(arity.ok);
  CHECK(says(arity, "main.cga:4:17: error[E016]: 'F.windowWidth' takes 1 argument, got 2"));
  const auto bare = compileImporting(head + "extrude(F.windowWidth) X.\n");
  CHECK_FALSE(bare.ok);
  CHECK(says(bare, "main.cga:4:17: error[E016]: 'F.windowWidth' takes 1 argument, got 0 (write F.windowWidth(...))"));
  const auto extra = compileImporting(head + "extrude(F.height(1)) X.\n");
  CHECK(says(extra, "main.cga:4:17: error[E016]: 'F.height' takes 0 arguments, got 1"));
  // A body with an error says it where it is written, once, and where it is called.
  const auto broken = compileImporting(head + "extrude(F.broken(1) + F.broken(2)) X.\n");
  CHECK_FALSE(broken.ok);
  CHECK(says(broken, "lib.cga:5:17: error[E010]: unknown name 'nosuch'"));
  CHECK(says(broken, "main.cga:4:17: note: 'F.broken' is called here"));
  const size_t first = broken.messages.find("error[E010]");
  CHECK(broken.messages.find("error[E010]", first + 1) == std::string::npos);  // said once
  // A function the library does not use is not an error of the library's own.
  CHECK(compileImporting(head + "X.\n").ok);
}

TEST_CASE("cga initialShape attributes: known members compile, others are located errors", "[cga][dialect]") {
  const auto ok = compileImporting(
      "@StartRule\nLot --> report(initialShape.name + initialShape.startRule, initialShape.origin.px + "
      "initialShape.origin.oy) X.\n");
  INFO(ok.messages);
  CHECK(ok.ok);
  const auto bad = compileImporting("@StartRule\nLot --> report(\"k\", initialShape.origin.qx) X.\n");
  CHECK_FALSE(bad.ok);
  CHECK(says(bad, "main.cga:2:21: error[E010]: unknown attribute 'initialShape.origin.qx' (initialShape.name, "
                  ".startRule, .origin.px|py|pz, .origin.ox|oy|oz)"));
}

TEST_CASE("cga styles: a style redefines attrs, chosen as Style$Rule, misuse is located", "[cga][dialect]") {
  const std::string styles =
      "attr h = 10\n@StartRule\nLot --> extrude(h) X.\nstyle Tall\nattr h = 20\nstyle Taller extends Tall\n";
  CHECK(compileImporting(styles).ok);
  CHECK(compileImporting(styles, "Taller$Lot").ok);
  CHECK(compileImporting(styles, "Default$Lot").ok);
  const auto unknownStyle = compileImporting(styles, "Short$Lot");
  CHECK_FALSE(unknownStyle.ok);
  CHECK(says(unknownStyle, "main.cga:1:1: error[E803]: --start-rule Short$Lot: this file has no style 'Short' (its "
                           "styles: Default, Tall, Taller)"));
  const auto base = compileImporting(styles + "style Wide extends Tal\n");
  CHECK(says(base, "main.cga:7:20: error[E803]: the style 'Wide' extends 'Tal', which is not a style of this file; "
                   "did you mean 'Tall'?"));
  CHECK(compileImporting(styles + "attr w = 3\n", "Taller$Lot").ok);  // a style's own attr (test_cga_styles.cpp)
  const auto twice = compileImporting(styles + "style Tall\n");
  CHECK(says(twice, "main.cga:7:7: error[E803]: the style 'Tall' is declared twice"));
}

TEST_CASE("cga import attribute lists: kept and set attrs, misuse is located", "[cga][dialect]") {
  CHECK(compileImporting("import F : \"lib.cga\" (floorHeight)\nattr floorHeight = 7\n@StartRule\nLot --> X.\n").ok);
  CHECK(compileImporting("import F : \"lib.cga\" (floorHeight = 2 * h)\nattr h = 7\n@StartRule\nLot --> X.\n").ok);
  CHECK(compileImporting("import F : \"lib.cga\" ()\n@StartRule\nLot --> X.\n").ok);
  const auto unknown = compileImporting("import F : \"lib.cga\" (nope)\n@StartRule\nLot --> X.\n");
  CHECK_FALSE(unknown.ok);
  CHECK(says(unknown, "main.cga:1:23: error[E062]: the module 'lib.cga' has no attr 'nope'"));
  const auto number = compileImporting("import F : \"lib.cga\" (3)\n@StartRule\nLot --> X.\n");
  CHECK_FALSE(number.ok);
  CHECK(says(number, "main.cga:1:23: error[E002]: an import's list names the imported file's attrs to keep"));
}

TEST_CASE("cga imported functions: nested calls that would copy past a million nodes are refused", "[cga][dialect]") {
  // sumTwice uses its parameter twice: n nested calls copy 2^n arguments into the body.
  const auto nested = [](int n) {
    std::string e = "1";
    for (int i = 0; i < n; ++i) e = "F.sumTwice(" + e + ")";
    return "import F : \"lib.cga\"\n@StartRule\nLot --> extrude(" + e + ") X.\n";
  };
  const auto ten = compileImporting(nested(10));
  INFO(ten.messages);
  CHECK(ten.ok);
  // 2^30 nodes: refused at once, located at the call that went past the limit, not a hang.
  const auto thirty = compileImporting(nested(30));
  INFO(thirty.messages);
  CHECK_FALSE(thirty.ok);
  CHECK(says(thirty, "error[E002]"));
  CHECK(says(thirty, "expands to more than 1000000 expression nodes"));
}

TEST_CASE("cga imports: the importer's value may read its attrs computed from other attrs", "[cga][dialect]") {
  const std::string tail = "@StartRule\nLot --> extrude(F.height) X.\n";
  // Computed attrs are known after the plain ones; the importer's value waits for them.
  const auto computed = compileImporting("import F : \"lib.cga\"\nattr base = 2\nattr fh = base * 2\nF.floorHeight = fh\n" + tail);
  INFO(computed.messages);
  CHECK(computed.ok);
  CHECK(computed.messages.empty());
  const auto random = compileImporting("import F : \"lib.cga\"\nattr fh = rand(2, 3)\nF.floorHeight = fh * 2\n" + tail);
  INFO(random.messages);
  CHECK(random.ok);
  // A shape query is still refused, with the importer's wording, at the value.
  const auto query = compileImporting("import F : \"lib.cga\"\nF.floorHeight = scope.sx\n" + tail);
  CHECK_FALSE(query.ok);
  CHECK(query.says("main.cga:2:17: error[E023]: the importer's value of attr 'F.floorHeight' may use numbers, "
                   "strings, consts, functions, other attrs, random numbers and math functions; not shape "
                   "queries or a cycle of attrs (CityEngine CGA; not supported yet)\n"));
}
