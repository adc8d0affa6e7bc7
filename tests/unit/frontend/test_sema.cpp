// Semantic analysis: names, arity, inferred types, bodies, probabilities, reachability.
#include "frontend/builtins.h"
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

TEST_CASE("In a CGA grammar a leaf outputs its own geometry, so it gets no W001", "[sema]") {
  auto cga = analyse("Lot ~> S(10, 0, 6) Extrude(3) Comp(\"sidefaces\"){ Wall };");
  CHECK(cga.ok);
  CHECK_FALSE(has(cga, "W001"));
  auto lsystem = analyse("derive parallel 2;\nLot ~> S(10, 0, 6) Leaf;");
  CHECK(has(lsystem, "W001"));
  // A leaf whose name is one slip from a symbol with rules is still pointed out.
  auto slip = analyse("Lot ~> S(10, 0, 6) Extrude(3) Comp(\"sidefaces\"){ Facde };\nFacade ~> Wall;");
  CHECK(has(slip, "W001", 1, 50));
  auto swapped = analyse("Lot ~> S(10, 0, 6) Extrude(3) Comp(\"sidefaces\"){ Fcaade };\nFacade ~> Wall;");
  CHECK(has(swapped, "W001"));
  auto cased = analyse("Lot ~> S(10, 0, 6) Extrude(3) Comp(\"sidefaces\"){ facade };\nFacade ~> Wall;");
  CHECK(has(cased, "W001"));
}

TEST_CASE("Labelled parts belong to Comp, name faces, and label every part", "[sema]") {
  CHECK(analyse("Lot ~> S(4, 3, 2) Comp(\"f\"){ front: A | side: B | top: C | all: D };").ok);
  auto wrongCommand = analyse("Lot ~> Subdiv(\"X\", 1r, 1r){ left: A | right: B };");
  CHECK(has(wrongCommand, "E018", 1, 29));
  auto unknown = analyse("Lot ~> S(4, 3, 2) Comp(\"f\"){ street: A };");
  CHECK(has(unknown, "E028", 1, 30));
  auto some = analyse("Lot ~> S(4, 3, 2) Comp(\"f\"){ front: A | B };");
  CHECK(has(some, "E018"));
  auto edges = analyse("Lot ~> S(4, 3, 2) Comp(\"edges\"){ top: A };");
  CHECK(has(edges, "E028"));
  // Edges take their roof classes as labels (issue #44); faces CityEngine's angle classes.
  CHECK(analyse("Lot ~> S(4, 3, 2) Comp(\"e\"){ eave: A | ridge: B | hip: C | valley: D | gable: E | all: F };").ok);
  CHECK(analyse("Lot ~> S(4, 3, 2) Comp(\"f\"){ horizontal: A | nutant: B };").ok);
  // Edges take CityEngine's direction selectors too (issue #44); an unknown one is located.
  CHECK(analyse("Lot ~> S(4, 3, 2) Comp(\"e\"){ eave: A | front: B };").ok);
  CHECK(has(analyse("Lot ~> S(4, 3, 2) Comp(\"e\"){ eave: A | inner: B };"), "E028", 1, 40));
  CHECK(has(analyse("Lot ~> S(4, 3, 2) Comp(\"f\"){ eave: A };"), "E028", 1, 30));
}

TEST_CASE("CGA split syntax: sizes on the parts and repeated patterns", "[sema]") {
  CHECK(analyse("Lot ~> S(10, 6, 0) Subdiv(\"Y\"){ 4: Ground | ~3: Floor };").ok);
  CHECK(analyse("attr h = 3;\nLot ~> S(10, 6, 0) Subdiv(\"Y\"){ h: Ground | 1r: Upper };").ok);
  CHECK(analyse("Lot ~> S(10, 6, 0) Subdiv(\"X\"){ ~1: Wall | 1.4: Window }*;").ok);
  CHECK(analyse("Lot ~> S(10, 6, 0) Subdiv(\"X\", 1, 2){ A | B }*;").ok);
  // Some parts sized, others not: located at the first size.
  CHECK(has(analyse("Lot ~> S(10, 6, 0) Subdiv(\"Y\"){ 4: Ground | Floor };"), "E018", 1, 33));
  // Sizes as arguments and on the parts.
  CHECK(has(analyse("Lot ~> S(10, 6, 0) Subdiv(\"Y\", 4, 2){ 4: Ground | 2: Floor };"), "E018"));
  // A number on a comp's part is an index selector (CityEngine's `comp(f){ 4 : A }`), not a size.
  CHECK(analyse("Lot ~> S(4, 3, 2) Comp(\"f\"){ 4: A };").ok);
  CHECK(has(analyse("Lot ~> S(10, 6, 0) Repeat(\"X\", 2){ A }*;"), "E018", 1, 20));
  // A relative size has no length to repeat by.
  CHECK(has(analyse("Lot ~> S(10, 6, 0) Subdiv(\"X\"){ 1r: A | 2: B }*;"), "E018", 1, 33));
}

TEST_CASE("Lot queries: area and properties with one constant default each", "[sema]") {
  CHECK(analyse("Lot ~> Footprint(0, 0, 4, 0, 4, 3) Extrude(Lot.prop(\"height\", 6) + Lot.area / 100) A;").ok);
  CHECK(has(analyse("Lot ~> S(1, 1, 1) T(Lot.width, 0, 0) A;"), "E025"));
  CHECK(has(analyse("attr h = 2;\nLot ~> S(1, 1, 1) T(Lot.prop(\"height\", h), 0, 0) A;"), "E025"));
  CHECK(has(analyse("Lot ~> S(Lot.prop(\"h\", 1), 1, 1) T(Lot.prop(\"h\", 2), 0, 0) A;"), "E025"));
  // The default's type is the property's: a string compared with a string.
  CHECK(analyse("Lot : Lot.prop(\"usage\", \"home\") == \"shop\" ~> S(1, 1, 1) A;").ok);
  // CGA's spelling Lot.props.height is Lot.prop("height", 0); no other query has three parts.
  CHECK(analyse("Lot ~> S(1, 1, 1) Extrude(Lot.props.height + Lot.prop(\"floors\", 0)) A;").ok);
  CHECK(has(analyse("Lot ~> S(1, 1, 1) Extrude(Lot.props.height + Lot.prop(\"height\", 14)) A;"), "E025"));
  CHECK(has(analyse("Lot ~> S(Scope.sx.y, 1, 1) A;"), "E025"));
}

TEST_CASE("Offset takes labelled inside and border parts", "[sema]") {
  CHECK(analyse("Lot ~> S(10, 0, 6) Offset(1){ inside: A | border: B };").ok);
  CHECK(has(analyse("Lot ~> S(10, 0, 6) Offset(1){ A };"), "E018"));
  CHECK(has(analyse("Lot ~> S(10, 0, 6) Offset(1){ middle: A };"), "E028"));
}

TEST_CASE("Footprint takes pairs of coordinates", "[sema]") {
  CHECK(analyse("Lot ~> Footprint(0, 0, 4, 0, 4, 3) Mass;").ok);
  CHECK(analyse("Lot ~> Footprint(0, 0, 9, 0, 9, 9, 0, 9, \"hole\", 3, 3, 6, 3, 6, 6) Mass;").ok);
  CHECK(analyse("Lot ~> Footprint((0, 0), (9, 0), (9, 9), (0, 9), \"hole\", (3, 3), (6, 3), (6, 6)) Mass;").ok);
  CHECK(has(analyse("Lot ~> Footprint(0, 0, 9, 0, 9, 9, 0, 9, \"court\", 3, 3, 6, 3, 6, 6) Mass;"), "E028", 1, 42));
  CHECK(has(analyse("Lot ~> Footprint(0, 0, 9, 0, 9, 9, 0, 9, \"hole\", 3, 3, 6, 3) Mass;"), "E016"));
  auto odd = analyse("Lot ~> Footprint(0, 0, 4, 0, 4, 3, 1) Mass;");
  CHECK_FALSE(odd.ok);
  CHECK(has(odd, "E016"));
  auto few = analyse("Lot ~> Footprint(0, 0, 4, 0) Mass;");
  CHECK(has(few, "E016"));
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
    surface torus(2, 0.6);
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

// ------------------------------------------------------------ collision and lines

namespace {

// Only the diagnostics with this code, as "line:col" strings.
std::vector<std::string> where(const Analysed& a, const std::string& code) {
  std::vector<std::string> out;
  for (const auto& d : a.diags)
    if (d.code == code)
      out.push_back(std::to_string(d.range.begin.line) + ":" + std::to_string(d.range.begin.col));
  return out;
}

std::string messageOf(const Analysed& a, const std::string& code) {
  for (const auto& d : a.diags)
    if (d.code == code) return d.message;
  return "";
}

const char* kRules = "\nA ~> I(\"cube\");";

}  // namespace

TEST_CASE("collision declarations: every form", "[sema][collision]") {
  auto none = analyse(std::string("A ~> I(\"cube\");"));
  REQUIRE(none.ok);
  CHECK_FALSE(none.sema.collisionDeclared);
  CHECK_FALSE(none.sema.collisionAll);
  CHECK(none.sema.collisionMetric == "mesh");

  auto all = analyse(std::string("collision all;") + kRules);
  REQUIRE(all.ok);
  CHECK(all.sema.collisionDeclared);
  CHECK(all.sema.collisionAll);
  CHECK(all.sema.collisionMetric == "mesh");
  CHECK(all.sema.collisionRange.begin.line == 1);

  auto mesh = analyse(std::string("collision mesh;") + kRules);
  REQUIRE(mesh.ok);
  CHECK_FALSE(mesh.sema.collisionAll);
  CHECK(mesh.sema.collisionMetric == "mesh");
  CHECK(mesh.sema.collisionRadius == 0);

  for (const char* spelling : {"centre", "center"}) {
    auto c = analyse(std::string("collision ") + spelling + " 0.3;" + kRules);
    REQUIRE(c.ok);
    CHECK_FALSE(c.sema.collisionAll);
    CHECK(c.sema.collisionMetric == "centre");
    CHECK(c.sema.collisionRadius == 0.3);
  }

  auto geo = analyse(std::string("collision geodesic 0.3;") + kRules);
  REQUIRE(geo.ok);
  CHECK(geo.sema.collisionMetric == "geodesic");
  CHECK(geo.sema.collisionRadius == 0.3);

  auto clearance = analyse(std::string("collision distance 0.05 omit;") + kRules);
  REQUIRE(clearance.ok);
  CHECK(clearance.sema.collisionMetric == "distance");
  CHECK(clearance.sema.collisionRadius == 0.05);
  CHECK(clearance.sema.collisionOmit);

  for (const char* text : {"collision all centre 0.25;", "collision centre 0.25 all;"}) {
    auto both = analyse(std::string(text) + kRules);
    REQUIRE(both.ok);
    CHECK(both.sema.collisionAll);
    CHECK(both.sema.collisionMetric == "centre");
    CHECK(both.sema.collisionRadius == 0.25);
  }

  // The radius may name a number const.
  auto named = analyse(std::string("const r = 0.5 / 2;\ncollision all geodesic r;") + kRules);
  REQUIRE(named.ok);
  CHECK(named.sema.collisionMetric == "geodesic");
  CHECK(named.sema.collisionRadius == 0.25);
}

TEST_CASE("collision declarations: each mistake with its code and column", "[sema][collision]") {
  // E030: an unknown word (the valid ones are listed), or no word at all.
  auto unknown = analyse(std::string("collision all centr 0.3;") + kRules);
  CHECK_FALSE(unknown.ok);
  CHECK(where(unknown, "E030") == std::vector<std::string>{"1:15"});
  CHECK(messageOf(unknown, "E030") ==
        "unknown collision setting 'centr' (expected all, omit, cull, mesh, centre R, center R, geodesic R or distance D)");
  CHECK(where(unknown, "E031") == std::vector<std::string>{"1:21"});  // its number, left over
  auto empty = analyse(std::string("collision;") + kRules);
  CHECK(where(empty, "E030") == std::vector<std::string>{"1:1"});
  auto stringConst = analyse(std::string("const r = \"x\";\ncollision centre r;") + kRules);
  CHECK(where(stringConst, "E031") == std::vector<std::string>{"2:11"});
  CHECK(where(stringConst, "E030") == std::vector<std::string>{"2:18"});

  // E031: centre / geodesic without a positive radius; a number anywhere else.
  auto missing = analyse(std::string("collision centre;") + kRules);
  CHECK_FALSE(missing.ok);
  CHECK(where(missing, "E031") == std::vector<std::string>{"1:11"});
  CHECK(messageOf(missing, "E031") == "'centre' needs a radius: `collision centre 0.3;`");
  auto missingBeforeAll = analyse(std::string("collision geodesic all;") + kRules);
  CHECK(where(missingBeforeAll, "E031") == std::vector<std::string>{"1:11"});
  auto zero = analyse(std::string("collision geodesic 0;") + kRules);
  CHECK(where(zero, "E031") == std::vector<std::string>{"1:20"});
  CHECK(messageOf(zero, "E031") == "the radius of 'geodesic' must be a positive number, got 0");
  auto noClearance = analyse(std::string("collision distance;") + kRules);
  CHECK(messageOf(noClearance, "E031") == "'distance' needs a clearance: `collision distance 0.3;`");
  auto zeroClearance = analyse(std::string("collision distance 0;") + kRules);
  CHECK(messageOf(zeroClearance, "E031") == "the clearance of 'distance' must be a positive number, got 0");
  auto negative = analyse(std::string("collision center -0.5;") + kRules);
  CHECK(where(negative, "E031") == std::vector<std::string>{"1:18"});
  CHECK(messageOf(negative, "E031") == "the radius of 'center' must be a positive number, got -0.5");
  auto stray = analyse(std::string("collision all 0.3;") + kRules);
  CHECK(where(stray, "E031") == std::vector<std::string>{"1:15"});
  CHECK(messageOf(stray, "E031") ==
        "a number in `collision` is the radius after 'centre', 'geodesic' or 'distance', and 'all' takes "
        "none: `collision centre 0.3;`");
  auto meshRadius = analyse(std::string("collision mesh 2;") + kRules);
  CHECK(where(meshRadius, "E031") == std::vector<std::string>{"1:16"});
  auto first = analyse(std::string("collision 0.3 centre 1;") + kRules);
  CHECK(where(first, "E031") == std::vector<std::string>{"1:11"});

  // E032: two metrics, a word twice, a second declaration.
  auto twoMetrics = analyse(std::string("collision mesh geodesic 0.2;") + kRules);
  CHECK_FALSE(twoMetrics.ok);
  CHECK(where(twoMetrics, "E032") == std::vector<std::string>{"1:16"});
  CHECK(messageOf(twoMetrics, "E032") ==
        "two collision metrics, 'mesh' and 'geodesic': choose one (mesh, centre R, geodesic R or distance D)");
  CHECK(where(twoMetrics, "E031").empty());  // geodesic's radius is still read as its radius
  auto allTwice = analyse(std::string("collision all centre 1 all;") + kRules);
  CHECK(where(allTwice, "E032") == std::vector<std::string>{"1:24"});
  auto second = analyse(std::string("collision all;\nA ~> I(\"cube\");\ncollision centre 0.3;"));
  CHECK_FALSE(second.ok);
  CHECK(where(second, "E032") == std::vector<std::string>{"3:1"});
  CHECK(messageOf(second, "E032") ==
        "only one `collision` declaration is allowed (the first is on line 1); write all its "
        "settings in one: `collision all centre 0.3;`");
  // The first declaration still counts.
  CHECK(second.sema.collisionAll);
  CHECK(second.sema.collisionMetric == "mesh");
}

TEST_CASE("Line and LineSeg: optional arguments, checked types, no body", "[sema][lines]") {
  auto ok = analyse(
      "Axiom ~> Line() LineSeg() Line(0.1) LineSeg(2) Line(0.1, false) Grow(3, true);\n"
      "Grow(n, m) ~> Line(n / 10, m && n > 1) LineSeg(n);");
  INFO(ok.diags.size());
  CHECK(ok.ok);
  CHECK(ok.diags.empty());

  auto types = analyse("Axiom ~> Line(\"wide\", 1) LineSeg(true);");
  CHECK_FALSE(types.ok);
  CHECK(where(types, "E013") == std::vector<std::string>{"1:15", "1:34"});
  CHECK(where(types, "E014") == std::vector<std::string>{"1:23"});
  CHECK(messageOf(types, "E014") == "the merge flag of 'Line' must be a boolean, but this is a number");

  auto arity = analyse("Axiom ~> Line(1, true, \"bark\", 2) LineSeg(1, 2);");
  CHECK(where(arity, "E016") == std::vector<std::string>{"1:10", "1:35"});
  CHECK(messageOf(arity, "E016") == "'Line' takes 0 to 3 arguments, got 4: Line(width, merge, \"asset\")");
  // The third argument, the asset drawn along the line, is a constant string.
  CHECK(analyse("Axiom ~> Line(1, true, \"bark\") LineSeg(1);").ok);
  CHECK(where(analyse("Axiom ~> Line(1, true, 2) LineSeg(1);"), "E017") == std::vector<std::string>{"1:24"});

  auto body = analyse("Axiom ~> Line(1){ A } LineSeg{ A };\nA ~> I(\"cube\");");
  CHECK(where(body, "E018") == std::vector<std::string>{"1:10", "1:23"});
}

TEST_CASE("IC and IM type-check and wait for no later issue", "[sema][collision]") {
  for (const char* name : {"IC", "IM", "Line", "LineSeg"}) {
    const CommandInfo* cmd = findCommand(name);
    REQUIRE(cmd != nullptr);
    CHECK(cmd->laterIssue == nullptr);
    CHECK(cmd->body == BodyRule::None);
  }
  auto ok = analyse("Axiom ~> IC(\"cube\") IM(\"cube\", 0.1, 30) A(0.2);\nA(d) ~> IM(\"ico\", d, d * 90);");
  CHECK(ok.ok);
  auto bad = analyse("Axiom ~> IM(\"cube\", \"far\", true);");
  CHECK(where(bad, "E013") == std::vector<std::string>{"1:21", "1:28"});
  auto asset = analyse("Axiom ~> IC(3);");
  CHECK(where(asset, "E017") == std::vector<std::string>{"1:13"});
}

TEST_CASE("a constant divided by zero is E027 at the divisor, alone", "[sema][constants]") {
  auto a = analyse("const z = 1 / (2 - 2);\nattr h = 3 % 0;\nAxiom ~> S(z, h, 1) I(\"cube\");\n");
  CHECK_FALSE(a.ok);
  REQUIRE(a.diags.size() == 2);
  CHECK(has(a, "E027", 1, 15));
  CHECK(has(a, "E027", 2, 14));
  CHECK(a.diags[0].message == "division by zero");
  // A constant that is not one for another reason is still E023, and its uses say nothing.
  auto b = analyse("const w = Rand(1, 2);\nAxiom ~> S(w, w, 1) I(\"cube\");\n");
  REQUIRE(b.diags.size() == 1);
  CHECK(has(b, "E023", 1, 11));
}

TEST_CASE("Color takes three numbers or a hex string", "[sema]") {
  CHECK(analyse("Axiom ~> Color(1, 0.5, 0) Color(\"#8C3b2e\") I(\"cube\");\n").ok);
  auto word = analyse("Axiom ~> Color(\"red\") I(\"cube\");\n");
  REQUIRE(word.diags.size() == 1);
  CHECK(has(word, "E042", 1, 16));
  auto two = analyse("Axiom ~> Color(1, 0) I(\"cube\");\n");
  REQUIRE(two.diags.size() == 1);
  CHECK(has(two, "E016", 1, 10));
  auto text = analyse("Axiom ~> Color(1, \"x\", 0) I(\"cube\");\n");
  CHECK_FALSE(text.ok);
}

TEST_CASE("derive parallel takes 0 to 2147483647 steps, larger is E029 with the range", "[sema]") {
  CHECK(analyse("derive parallel 2147483647;\naxiom: F(1);\nF(l) -> F(l);\n").sema.steps == 2147483647);
  for (const char* steps : {"2147483648", "4294967297", "1e300", "-1", "2.5"}) {
    INFO(steps);
    auto a = analyse(std::string("derive parallel ") + steps + ";\naxiom: F(1);\nF(l) -> F(l);\n");
    CHECK_FALSE(a.ok);
    REQUIRE(a.diags.size() == 1);
    CHECK(has(a, "E029", 1, 17));
    CHECK_THAT(a.diags[0].message, Catch::Contains("N from 0 to 2147483647"));
  }
  auto a = analyse("derive parallel 4294967297;\naxiom: F(1);\nF(l) -> F(l);\n");
  CHECK_THAT(a.diags[0].message, Catch::EndsWith(", got 4294967297"));
  auto z = analyse("derive parallel 4 / 0;\naxiom: F(1);\nF(l) -> F(l);\n");
  REQUIRE(z.diags.size() == 1);
  CHECK(has(z, "E027", 1, 21));
  // An attr as N: its default checked here, its value when the grammar runs.
  auto attr = analyse("attr n = 7;\nderive parallel n;\naxiom: F(1);\nF(l) -> F(l);\n");
  CHECK(attr.ok);
  CHECK(attr.sema.steps == 7);
  CHECK(attr.sema.countAttr == "n");
  auto half = analyse("attr n = 2.5;\nderive parallel n;\naxiom: F(1);\nF(l) -> F(l);\n");
  REQUIRE(half.diags.size() == 1);
  CHECK(has(half, "E029", 2, 17));
  CHECK_THAT(half.diags[0].message, Catch::EndsWith(", got 2.5 (the default of attr 'n')"));
  auto t = analyse("turtle angle 90 % (1 - 1);\naxiom: F(1);\nF(l) -> F(l);\n");
  REQUIRE(t.diags.size() == 1);
  CHECK(has(t, "E027", 1, 19));
}

// ------------------------------------------------------------ ABOP turtle symbols

TEST_CASE("rules for turtle symbols make them shape symbols, and #ignore names symbols", "[sema][abop]") {
  auto a = analyse(R"(
    derive parallel 3;
    #ignore: + - F b Q;
    axiom: F b + a;
    a < b > a -> b;
    + -> -;
    !(w) -> !(w * 0.5);
    b -> !(1) b;
  )");
  REQUIRE(a.ok);
  const int plus = a.sema.findSymbol("+");
  REQUIRE(plus >= 0);
  CHECK(a.sema.symbols[plus].rules.size() == 1);
  const int bang = a.sema.findSymbol("!");
  REQUIRE(bang >= 0);
  CHECK(a.sema.symbols[bang].params.size() == 1);
  CHECK(a.sema.findSymbol("-") < 0);  // used, but no rule: still the turtle command
  // + (which has a rule) and b are symbols; F and - are commands (always stepped
  // over); Q is neither.
  CHECK(a.sema.contextIgnored == std::vector<std::string>{"+", "b"});
  CHECK(where(a, "W006") == std::vector<std::string>{"3:22"});
  CHECK_THAT(messageOf(a, "W006"), Catch::Contains("'Q'"));

  // A turtle symbol with rules keeps one arity, as every shape symbol does.
  auto arity = analyse(R"(
    derive parallel 1;
    axiom: + +(30);
    + -> -;
  )");
  CHECK_FALSE(arity.ok);
  CHECK(has(arity, "E019"));
}

TEST_CASE("#consider (lpfg) and consider: / ignore: (cpfg, L-Py) list the symbols context matching sees", "[sema][abop]") {
  // Symbols in the order first met: b, a (rule heads and contexts), then c. F without rules
  // is a command (stepped over anyway: W006 says #consider cannot make a context see it);
  // Q is no symbol.
  auto a = analyse(R"(
    derive parallel 3;
    #consider: a b F Q;
    axiom: F b + a c;
    a < b > a -> b;
    c -> c;
  )");
  REQUIRE(a.ok);
  CHECK(a.sema.contextIgnored == std::vector<std::string>{"c"});
  CHECK(where(a, "W006") == std::vector<std::string>{"3:20", "3:22"});
  CHECK_THAT(a.diags[0].message, Catch::Contains("'F', a turtle command"));
  // cpfg's and L-Py's bare forms, the ';' optional; both lists: seen when considered and
  // not ignored.
  for (const char* lists : {"consider: a b\n", "consider: a b;\n", "ignore: c\n", "#consider: a b c;\nignore: c\n"}) {
    INFO(lists);
    auto bare = analyse(std::string("derive parallel 1;\n") + lists + "axiom: b a c;\na < b -> b;\nc -> c;\n");
    REQUIRE(bare.ok);
    CHECK(bare.sema.contextIgnored == std::vector<std::string>{"c"});
  }
  // `ignore` followed by a guard and an arrow is a rule for a symbol named so.
  auto rule = analyse("derive parallel 1;\naxiom: ignore;\nignore : 1 > 0 -> ignore;\n");
  REQUIRE(rule.ok);
  CHECK(rule.sema.findSymbol("ignore") >= 0);
  CHECK(rule.sema.contextIgnored.empty());
}

TEST_CASE("turtle colors: a string of #rrggbb colours", "[sema][abop]") {
  auto good = analyse("turtle colors \"#ff0000  #00FF80\";\naxiom: F ' F;");
  REQUIRE(good.ok);
  REQUIRE(good.sema.turtleColors.size() == 2);
  CHECK(good.sema.turtleColors[1][1] == 1.0f);
  CHECK(good.sema.turtleColors[1][2] == Approx(128.0 / 255));
  for (const char* bad : {"\"\"", "\"#ff00\"", "\"red\"", "3"}) {
    INFO(bad);
    auto a = analyse(std::string("turtle colors ") + bad + ";\naxiom: F;");
    CHECK(has(a, "E029", 1));
  }
}

TEST_CASE("Synthesize names its parts' symbol only for a polygonal example", "[sema]") {
  auto ok = analyse("axiom: S(9, 3, 9) A;\nA ~> Synthesize(\"house.obj\", 9, 3, 9, \"H\");\nH ~> Comp(\"f\"){ vertical: W | aslant: R };\nW ~> I(\"cube\");\nR ~> I(\"cube\");");
  CHECK(ok.ok);
  auto grid = analyse("axiom: S(9, 3, 9) A;\nA ~> Synthesize(\"castle.txt\", 9, 3, 9, \"H\");\nH ~> I(\"cube\");");
  CHECK(has(grid, "E064", 2, 40));
  auto unknown = analyse("axiom: S(9, 3, 9) A;\nA ~> Synthesize(\"house.obj\", 9, 3, 9, \"Hose\");\nH ~> I(\"cube\");");
  CHECK(has(unknown, "E064", 2, 39));
  auto number = analyse("axiom: S(9, 3, 9) A;\nA ~> Synthesize(\"house.obj\", 9, 3, 9, 4);");
  CHECK(has(number, "E017", 2, 39));
  auto part = analyse("A ~> Comp(\"f\"){ slanted: B };\nB ~> I(\"cube\");");
  CHECK(has(part, "E028", 1, 17));
}

TEST_CASE("L-system hints: ABOP's modules written together, query modules without rules", "[sema]") {
  const auto says = [](const Analysed& a, const std::string& code, const std::string& text) {
    for (const auto& d : a.diags)
      if (d.code == code && d.message.find(text) != std::string::npos) return true;
    return false;
  };
  // ABOP's F1F1F1 (Fig. 1.31) is one name in fgsg: its W001 says how to write it.
  auto glued = analyse("derive parallel 2;\naxiom: F1F1F1;");
  CHECK(says(glued, "W001", "separate the modules with spaces"));
  auto word = analyse("derive parallel 2;\naxiom: Floor2;");
  CHECK(has(word, "W001"));
  CHECK_FALSE(says(word, "W001", "separate the modules"));
  // L-Py's and lpfg's '_' (width) is an ordinary name in fgsg: its W001 points at !(w).
  auto underscore = analyse("derive parallel 2;\naxiom: F _ F;");
  CHECK(says(underscore, "W001", "set the width with !(w)"));
  // A query module holds the turtle's values and draws nothing: no W001 without rules.
  auto query = analyse("derive parallel 2;\naxiom: A ?P(0, 0, 0);\nA > ?P(x, y, z) : y < 3 -> F A;");
  CHECK(query.ok);
  CHECK_FALSE(has(query, "W001"));
}
