// Semantic analysis: names, arity, inferred types, bodies, probabilities, reachability.
#include "frontend/parse.h"
#include "frontend/sema.h"

#include <catch2/catch.hpp>

using namespace fgsg::frontend;

namespace {

struct Analysed {
  SourceFile file;
  Program program;
  SemaResult sema;
  std::vector<Diagnostic> diags;
  bool ok = false;
};

Analysed analyse(const std::string& text) {
  Analysed a;
  a.file = SourceFile::make("t.fgsg", text);
  Diagnostics diags(&a.file);
  REQUIRE(parseProgram(a.file, a.program, diags));
  a.ok = analyze(a.program, a.sema, diags);
  a.diags = diags.all();
  return a;
}

bool has(const Analysed& a, const std::string& code, int line = 0, int col = 0) {
  for (const auto& d : a.diags)
    if (d.code == code && (line == 0 || d.range.begin.line == line) &&
        (col == 0 || d.range.begin.col == col))
      return true;
  return false;
}

}  // namespace

TEST_CASE("Parameter types are inferred from the places shapes are created", "[sema]") {
  auto a = analyse(R"(
    Axiom ~> Part("door", 2, true, (1, 2, 3));
    Part(name, n, flag, v) : flag && name == "door" ~> T(n, 0, 0) I("cube");
  )");
  REQUIRE(a.ok);
  const auto& part = a.sema.symbols[a.sema.findSymbol("Part")];
  REQUIRE(part.params.size() == 4);
  CHECK(part.params[0] == ValueType::Str);
  CHECK(part.params[1] == ValueType::Num);
  CHECK(part.params[2] == ValueType::Bool);
  CHECK(part.params[3] == ValueType::Vec3);
}

TEST_CASE("Types flow through recursion to a fixed point", "[sema]") {
  auto a = analyse(R"(
    Axiom ~> A(0, "x");
    A(n, s) : n < 3 ~> A(n + 1, s);
  )");
  REQUIRE(a.ok);
  CHECK(a.sema.symbols[a.sema.findSymbol("A")].params[1] == ValueType::Str);
}

TEST_CASE("Conflicting argument types are errors", "[sema]") {
  auto a = analyse("Axiom ~> A(1) A(\"one\");\nA(n) ~> I(\"cube\");");
  CHECK_FALSE(a.ok);
  CHECK(has(a, "E020", 1, 17));
}

TEST_CASE("Unknown names, functions and bad arity are reported where they are", "[sema]") {
  auto a = analyse("Axiom ~> T(wdth, 0, 0) S(1, 1) I(\"cube\") A(sinn(1));\nA(x) ~> I(\"cube\");");
  CHECK_FALSE(a.ok);
  CHECK(has(a, "E010", 1, 12));
  CHECK(has(a, "E016", 1, 24));
  CHECK(has(a, "E011", 1, 44));
}

TEST_CASE("Guards must be boolean and sizes 1r only where sizes go", "[sema]") {
  auto a = analyse("A : 1 + 2 ~> T(1r, 0, 0) I(\"cube\");");
  CHECK_FALSE(a.ok);
  CHECK(has(a, "E014", 1, 5));
  CHECK(has(a, "E026", 1, 16));
  auto ok = analyse("axiom: S(10, 1, 1) A;\nA ~> S(1r, 2, ~1) Subdiv(\"X\", 1r, ~2){ B | B };\nB ~> I(\"cube\");");
  CHECK(ok.ok);
}

TEST_CASE("Split bodies must match their sizes", "[sema]") {
  auto a = analyse("A ~> Subdiv(\"X\", 1, 2){ B };\nB ~> I(\"cube\");");
  CHECK(has(a, "E018", 1, 6));
  auto axes = analyse("A ~> Repeat(\"XQ\", 1, 2){ B };\nB ~> I(\"cube\");");
  CHECK(has(axes, "E028", 1, 13));
  auto comp = analyse("A ~> Comp(\"walls\"){ B };\nB ~> I(\"cube\");");
  CHECK(has(comp, "E028", 1, 11));
}

TEST_CASE("Probability sanity", "[sema]") {
  auto sum = analyse("A ~> I(\"cube\") : 0.2 ~> I(\"ico\") : 0.3;");
  CHECK(sum.ok);
  CHECK(has(sum, "W003", 1, 1));
  auto negative = analyse("A ~> I(\"cube\") : -1;");
  CHECK_FALSE(negative.ok);
  CHECK(has(negative, "E015"));
}

TEST_CASE("Symbols without rules and rules that never apply are warned about", "[sema]") {
  auto a = analyse("Axiom ~> A Stray;\nA ~> I(\"cube\");\nOrphan ~> I(\"cube\");");
  CHECK(a.ok);
  CHECK(has(a, "W001", 1, 12));
  CHECK(has(a, "W002", 3, 1));
}

TEST_CASE("The start symbol is Axiom, start, or the first rule's predecessor", "[sema]") {
  CHECK(analyse("X ~> Y;\nstart ~> X;\nY ~> I(\"cube\");").sema.startSymbol == "start");
  CHECK(analyse("Lot ~> I(\"cube\");").sema.startSymbol == "Lot");
  auto none = analyse("A(n) ~> I(\"cube\");");
  CHECK_FALSE(none.ok);
  CHECK(has(none, "E024"));
}

TEST_CASE("Queries: fields must be declared, Scope and Shape members exist", "[sema]") {
  auto a = analyse("S : F1.mincurv >= 0 ~> I(\"cube\");");
  CHECK(has(a, "E025", 1, 5));
  auto ok = analyse(R"(
    field F1 = curvature;
    texture mask = "paint.png";
    G : F1.mincurv >= 0 && context.mask(texCoord) > 0.5 && Scope.sx > 1 && Shape.depth < 4
      ~> T(F1.value1, 0, 0) I("cube");
  )");
  CHECK(ok.ok);
  auto bad = analyse("A : Scope.volume > 1 ~> I(\"cube\");");
  CHECK(has(bad, "E025", 1, 5));
}

TEST_CASE("Constants are evaluated and must be constant", "[sema]") {
  auto a = analyse("const w = 2 * 3;\nconst h = w + 1;\nattr n = h * 2;\nA ~> I(\"cube\");");
  REQUIRE(a.ok);
  CHECK(a.sema.constants.at("h").num == 7);
  CHECK(a.sema.attrs[0].value.num == 14);
  auto bad = analyse("attr n = 3;\nconst w = n * 2;\nA ~> I(\"cube\");");
  CHECK(has(bad, "E023", 2, 11));
  auto twice = analyse("const w = 1;\nconst w = 2;\nA ~> I(\"cube\");");
  CHECK(has(twice, "E022", 2, 1));
}

TEST_CASE("Constant vectors and two-argument math fold", "[sema]") {
  auto a = analyse("const v = (1, 2, 3);\nconst w = max(2, pow(2, 3));\nA ~> I(\"cube\");");
  REQUIRE(a.ok);
  CHECK(a.sema.constants.at("v").type == ValueType::Vec3);
  CHECK(a.sema.constants.at("v").vec[2] == 3);
  CHECK(a.sema.constants.at("w").num == 8);
}
