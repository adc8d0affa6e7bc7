// The `.cga` dialect's front end: CityEngine CGA syntax translated into fgsg's AST and
// checked like any grammar — every syntax item, case chains whose first true condition
// wins, stochastic weights, inlined functions, annotations, and located errors for what
// cannot run yet (and for CityEngine operations written in the fgsg dialect).
#include "cga_compile_helpers.h"

#include "frontend/cga/cga_parse.h"
#include "ir/ir.h"
#include "ir/pipeline.h"
#include "ir/printer.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <sstream>

using namespace fgsg;

namespace {

using Compiled = frontend::test::CgaCompiled;

Compiled compile(const std::string& text, const std::string& name = "test.cga") {
  return frontend::test::compileGrammarText(text, name);
}

const ir::Rule* firstRule(const ir::Module& m, const std::string& symbol, size_t n = 0) {
  const int s = m.findSymbol(symbol);
  if (s < 0 || m.symbols[size_t(s)].rules.size() <= n) return nullptr;
  return &m.rules[m.symbols[size_t(s)].rules[n]];
}

}  // namespace

TEST_CASE("which files are CGA", "[cga][dialect]") {
  CHECK(frontend::isCgaSource("rules/building.cga", ""));
  CHECK_FALSE(frontend::isCgaSource("building.fgsg", "Lot ~> A;"));
  CHECK(frontend::isCgaSource("x.fgsg", "// CityEngine\n  dialect cga;\nLot --> X."));
  CHECK_FALSE(frontend::isCgaSource("x.fgsg", "attr dialect = 2;"));
  CHECK(frontend::cgaLookingLine("attr a = 1\n\nLot --> extrude(3)\n") == 3);
  CHECK(frontend::cgaLookingLine("Lot ~> A; // --> in a comment is fine\n") == 1);  // not at line start
  CHECK(frontend::cgaLookingLine("// Lot --> A\nLot ~> A;") == 0);
}

TEST_CASE("every syntax item of a CityEngine rule file compiles", "[cga][dialect]") {
  const Compiled c = compile(R"(version "2023.0"
# a hash comment
// a line comment
/* a block
   comment */
@Range(min=1, max=10, stepsize=0.5) @Group("Mass", 1) @Order(2) @Description("how high")
attr height = 8
@Enum("red", "green") attr tint = "red"
@Hidden @Color attr roof = "#f00"
@Angle @Percent @Distance @File @Directory @Handle(shape=Lot, axis=y) attr misc = 1
const half = height / 2
const flag = true
const choice = 30% : "a" 20% : "b" else : "c"
twice(x) = 2 * x
level(h) = case h > 6 : 2 case h > 3 : 1 else : 0

@StartRule
Lot --> extrude(height) comp(f) { top : Top | side = Side | bottom : NIL }
Top --> case flag && !(height < 2) || false : roofHip(30) Roof. else : X.
Side --> split(y, noAdjust) { '0.25 : A | ~twice(1) : B | { 2 : C | ~1 : D }* | 1 : . }
A --> s('1, '0.5, 0) t(0, '0.5, 0) r(scopeCenter, 0, 90, 0) center(xz) color("#0f0") A2(level(height), choice)
A2(n, s) --> 50% : [ t(0, 1, 0) B ] X. 25%: NIL else : color(0.1, 0.2, 0.3) i("builtin:cube")
B --> split(x) { 1 : C }*
C --> set(material.color.rgb, "#123456") print("c") D
D --> offset(-0.1, inside) Inner.
)");
  INFO(c.messages);
  REQUIRE(c.ok);
  // comp(f)'s `=` merges the faces it takes into one shape: no warning.
  CHECK(c.messages.find("W800") == std::string::npos);
  // The annotations are the attr's metadata.
  const int h = c.module.findAttr("height");
  REQUIRE(h >= 0);
  const auto& notes = c.module.attrs[size_t(h)].annotations;
  REQUIRE(notes.size() == 4);
  CHECK(notes[0].name == "Range");
  REQUIRE(notes[0].args.size() == 3);
  CHECK(notes[0].args[0] == std::make_pair(std::string("min"), std::string("1")));
  CHECK(notes[0].args[2] == std::make_pair(std::string("stepsize"), std::string("0.5")));
  CHECK(notes[1].name == "Group");
  CHECK(notes[1].args[0].second == "Mass");
  CHECK(notes[3].name == "Description");
  const int tint = c.module.findAttr("tint");
  REQUIRE(tint >= 0);
  REQUIRE(c.module.attrs[size_t(tint)].annotations.size() == 1);
  CHECK(c.module.attrs[size_t(tint)].annotations[0].args.size() == 2);
  // The printed IR shows them, and the split's CityEngine sizing.
  const std::string ir = ir::printModule(c.module);
  CHECK(ir.find("@Range(min=1, max=10, stepsize=0.5)") != std::string::npos);
  CHECK(ir.find("cityengine") != std::string::npos);
}

TEST_CASE("a case chain: the first condition that holds wins", "[cga][dialect]") {
  const Compiled c = compile("attr h = 5\n@StartRule\nLot --> case h > 3 : A case h > 1 : B else : C\n");
  INFO(c.messages);
  REQUIRE(c.ok);
  // Three rules for Lot, guards h > 3; !(h > 3) && h > 1; !(h > 3) && !(h > 1).
  const int lot = c.module.findSymbol("Lot");
  REQUIRE(lot >= 0);
  REQUIRE(c.module.symbols[size_t(lot)].rules.size() == 3);
  for (uint32_t r : c.module.symbols[size_t(lot)].rules) CHECK(c.module.rules[r].hasGuard);
  const std::string ir = ir::printModule(c.module);
  CHECK(ir.find("!(") != std::string::npos);
}

TEST_CASE("a stochastic rule's branches have the percentages as weights", "[cga][dialect]") {
  const Compiled c = compile("@StartRule\nLot --> 30% : A 20% : B else : C\n");
  INFO(c.messages);
  REQUIRE(c.ok);
  const ir::Rule* r = firstRule(c.module, "Lot");
  REQUIRE(r);
  REQUIRE(r->alternatives.size() == 3);
  CHECK(r->alternatives[0].probability.num == Approx(0.3));
  CHECK(r->alternatives[1].probability.num == Approx(0.2));
  CHECK(r->alternatives[2].probability.num == Approx(0.5));
  // Without `else` the rest of the time the shape is removed.
  const Compiled d = compile("@StartRule\nLot --> 40% : A\n");
  REQUIRE(d.ok);
  const ir::Rule* q = firstRule(d.module, "Lot");
  REQUIRE(q);
  REQUIRE(q->alternatives.size() == 2);
  CHECK(q->alternatives[1].probability.num == Approx(0.6));
  CHECK(q->alternatives[1].ops.empty());
}

TEST_CASE("functions are inlined, and recursion is a located error", "[cga][dialect]") {
  const Compiled c = compile("f(x) = x * 2 + 1\ng = f(3)\n@StartRule\nLot --> s(g, f(1), 1) X.\n");
  INFO(c.messages);
  REQUIRE(c.ok);
  const std::string ir = ir::printModule(c.module);
  CHECK(ir.find("7") != std::string::npos);  // folded: 3 * 2 + 1
  const Compiled r = compile("f(x) = g(x)\ng(x) = f(x) + 1\n@StartRule\nLot --> s(f(1), 1, 1) X.\n");
  CHECK_FALSE(r.ok);
  CHECK(r.messages.find("E802") != std::string::npos);
  CHECK(r.messages.find("test.cga:2:8: error[E802]: 'f' calls itself (through g)") != std::string::npos);
}

TEST_CASE("roofRidge(byAngle, angle) is fgsg's ridge roof, its other forms located errors", "[cga][dialect]") {
  const Compiled c = compile("@StartRule\nLot --> extrude(3) comp(f) { top : roofRidge(byAngle, 30) Roof }\n");
  INFO(c.messages);
  REQUIRE(c.ok);
  CHECK(ir::printModule(c.module).find("roof \"ridge\" 30") != std::string::npos);
  const Compiled height = compile("@StartRule\nLot --> roofRidge(byHeight, 3) A\n");
  INFO(height.messages);
  REQUIRE(height.ok);
  CHECK(ir::printModule(height.module).find("roof \"ridge\" byHeight 3") != std::string::npos);
  const Compiled bare = compile("@StartRule\nLot --> roofRidge(30) A\n");
  CHECK(bare.messages.find("test.cga:2:9: error[E016]: 'roofRidge' takes byAngle or byHeight and a value, got 1") !=
        std::string::npos);
  const Compiled word = compile("@StartRule\nLot --> roofRidge(bySlope, 30) A\n");
  CHECK(word.messages.find("test.cga:2:19: error[E028]: roofRidge's value type is byAngle or byHeight, "
                           "not 'bySlope'") != std::string::npos);
  const Compiled kind = compile("axiom: Lot;\nLot ~> Roof(\"ridged\", 30){ R };\n", "test.fgsg");
  CHECK(kind.messages.find("error[E028]: unknown roof kind \"ridged\" (hipped, gable, pyramid, shed or ridge)") !=
        std::string::npos);
}

TEST_CASE("roofs by height (#44): Roof(kind, \"byHeight\", h, ...) in both dialects, bad forms located errors",
          "[cga][dialect]") {
  const Compiled cga = compile("@StartRule\nLot --> roofHip(byHeight, 3, 0.5) A.\n");
  INFO(cga.messages);
  REQUIRE(cga.ok);
  CHECK(ir::printModule(cga.module).find("roof \"hipped\" byHeight 3, 0.5") != std::string::npos);
  for (const char* op : {"roofGable(byHeight, 2, 1, 0.5, false)", "roofPyramid(byHeight, 4)", "roofShed(byHeight, 2, 1)",
                         "roofGable(byAngle, 30, 1)"}) {
    const Compiled c = compile(std::string("@StartRule\nLot --> ") + op + " A.\n");
    INFO(op << "\n" << c.messages);
    CHECK(c.ok);
  }
  const Compiled many = compile("@StartRule\nLot --> roofHip(byHeight, 3, 1, false, 2) A.\n");
  CHECK(many.messages.find("test.cga:2:9: error[E016]: 'roofHip' takes byHeight, a height, overhang and even, got 5") !=
        std::string::npos);
  const Compiled fgsg = compile("axiom: Lot;\nLot ~> Roof(\"gable\", \"byHeight\", 2, 1){ Top };\n", "test.fgsg");
  INFO(fgsg.messages);
  REQUIRE(fgsg.ok);
  CHECK(ir::printModule(fgsg.module).find("roof \"gable\" byHeight 2, 1") != std::string::npos);
  const Compiled byAngle = compile("axiom: Lot;\nLot ~> Roof(\"gable\", \"byAngle\", 30){ Top };\n", "test.fgsg");
  INFO(byAngle.messages);
  REQUIRE(byAngle.ok);
  CHECK(ir::printModule(byAngle.module).find("roof \"gable\" 30") != std::string::npos);
  const Compiled word = compile("axiom: Lot;\nLot ~> Roof(\"gable\", \"bySlope\", 2){ Top };\n", "test.fgsg");
  CHECK(word.messages.find("test.fgsg:2:22: error[E028]: Roof's value type is \"byAngle\" or \"byHeight\", not "
                           "\"bySlope\"") != std::string::npos);
  const Compiled bare = compile("axiom: Lot;\nLot ~> Roof(\"gable\", \"byHeight\"){ Top };\n", "test.fgsg");
  CHECK(bare.messages.find("test.fgsg:2:8: error[E016]: 'Roof' with \"byHeight\" takes the value after it") !=
        std::string::npos);
  const Compiled six = compile("axiom: Lot;\nLot ~> Roof(\"gable\", 30, 1, 1, 0, 2){ Top };\n", "test.fgsg");
  CHECK(six.messages.find("test.fgsg:2:8: error[E016]: 'Roof' takes 2 to 5 arguments, got 6") != std::string::npos);
}

TEST_CASE("geometry.angle(maxSlope | azimuth | zenith) is fgsg's Geometry.angle, other selectors errors",
          "[cga][dialect]") {
  const Compiled c = compile("@StartRule\nLot --> report(\"a\", geometry.angle(maxSlope) + geometry.angle(azimuth) + "
                             "geometry.angle(zenith)) X.\n");
  INFO(c.messages);
  REQUIRE(c.ok);
  const std::string printed = ir::printModule(c.module);
  CHECK(printed.find("Geometry.angle(\"maxSlope\")") != std::string::npos);
  CHECK(printed.find("Geometry.angle(\"azimuth\")") != std::string::npos);
  CHECK(printed.find("Geometry.angle(\"zenith\")") != std::string::npos);
  const Compiled word = compile("@StartRule\nLot --> s(geometry.angle(minSlope), 1, 1) X.\n");
  CHECK(word.messages.find("test.cga:2:26: error[E028]: geometry.angle's selector is maxSlope, azimuth or zenith, "
                           "not 'minSlope'") != std::string::npos);
  const Compiled none = compile("@StartRule\nLot --> s(geometry.angle(), 1, 1) X.\n");
  CHECK(none.messages.find("test.cga:2:11: error[E016]: 'geometry.angle' takes 1 argument (maxSlope, azimuth or "
                           "zenith), got 0") != std::string::npos);
  const Compiled fgsg = compile("axiom: Lot;\nLot ~> S(Geometry.angle(\"steepest\"), 1, 1) X;\n", "test.fgsg");
  CHECK(fgsg.messages.find("test.fgsg:2:10: error[E025]: Geometry.angle takes the constant \"maxSlope\", "
                           "\"azimuth\" or \"zenith\"") != std::string::npos);
  CHECK(compile("axiom: Lot;\nLot ~> S(Geometry.angle(\"zenith\"), 1, 1) X;\n", "test.fgsg").ok);
}

TEST_CASE("geometry.du/dv(k, uvSpace) are fgsg's Geometry.du/dv of uv set k, other sets and unitSpace located errors",
          "[cga][dialect]") {
  const Compiled c = compile("@StartRule\nLot --> report(\"u\", geometry.du(0, uvSpace) + geometry.dv(3, uvSpace)) X.\n");
  INFO(c.messages);
  REQUIRE(c.ok);
  // Set 0 prints as before (the same IR); another set names itself.
  const std::string printed = ir::printModule(c.module);
  CHECK(printed.find("Geometry.du +") != std::string::npos);
  CHECK(printed.find("Geometry.dv(3, \"uvSpace\")") != std::string::npos);
  const Compiled set = compile("@StartRule\nLot --> s(geometry.du(10, uvSpace), 1, 1) X.\n");
  CHECK(set.messages.find("test.cga:2:23: error[E028]: a uv set is a whole number from 0 to 9") != std::string::npos);
  const Compiled unit = compile("@StartRule\nLot --> s(geometry.dv(0, unitSpace), 1, 1) X.\n");
  CHECK(unit.messages.find("test.cga:2:26: error[E801]: 'geometry.dv' in unitSpace") != std::string::npos);
  const Compiled word = compile("@StartRule\nLot --> s(geometry.du(0, uv), 1, 1) X.\n");
  CHECK(word.messages.find("test.cga:2:26: error[E028]: geometry.du's surface parameterization is uvSpace or "
                           "unitSpace, not 'uv'") != std::string::npos);
  const Compiled none = compile("@StartRule\nLot --> s(geometry.du(), 1, 1) X.\n");
  CHECK(none.messages.find("test.cga:2:11: error[E016]: 'geometry.du' takes 2 arguments") != std::string::npos);
  const Compiled fgsg = compile("axiom: Lot;\nLot ~> S(Geometry.du(10, \"uvSpace\"), 1, 1) X;\n", "test.fgsg");
  CHECK(fgsg.messages.find("test.fgsg:2:10: error[E025]: Geometry.du reads a uv set, a constant whole number from 0 "
                           "to 9") != std::string::npos);
  const Compiled half = compile("axiom: Lot;\nLot ~> S(Geometry.du(1.5, \"uvSpace\"), 1, 1) X;\n", "test.fgsg");
  CHECK(half.messages.find("test.fgsg:2:10: error[E025]") != std::string::npos);
  const Compiled space = compile("axiom: Lot;\nLot ~> S(Geometry.dv(0, \"unitSpace\"), 1, 1) X;\n", "test.fgsg");
  CHECK(space.messages.find("error[E025]: Geometry.dv measures in \"uvSpace\"") != std::string::npos);
  CHECK(compile("axiom: Lot;\nLot ~> S(Geometry.dv(9, \"uvSpace\"), 1, 1) X;\n", "test.fgsg").ok);
}

TEST_CASE("setback's index selectors are whole numbers in both dialects", "[cga][dialect]") {
  const Compiled c = compile("@StartRule\nLot --> setbackPerEdge(1) { 0 : A | -1 = B | remainder : C }\n");
  INFO(c.messages);
  REQUIRE(c.ok);
  const Compiled fraction = compile("@StartRule\nLot --> setback(1) { 1.5 : A | remainder : C }\n");
  CHECK(fraction.messages.find("test.cga:2:22: error[E801]: the selector '1.5' of setback") != std::string::npos);
  CHECK(compile("axiom: Lot;\nLot ~> Setback(1){ 2: A | -1: B | remainder: C };\n", "test.fgsg").ok);
  const Compiled size = compile("axiom: Lot;\nLot ~> Setback(1){ 1.5: A | remainder: C };\n", "test.fgsg");
  CHECK(size.messages.find("test.fgsg:2:20: error[E018]: a size label `4:` belongs to a part of Subdiv") !=
        std::string::npos);
}

TEST_CASE("what the dialect cannot run yet is an error at its name", "[cga][dialect]") {
  const Compiled reduce = compile("@StartRule\nLot --> extrude(10)\n   reduceGeometry()\n");
  CHECK_FALSE(reduce.ok);
  CHECK(reduce.messages.find(
            "test.cga:3:4: error[E800]: unknown operation 'reduceGeometry' (CityEngine CGA; not supported yet)") !=
        std::string::npos);
  const Compiled unknown = compile("@StartRule\nLot --> frobnicate(3)\n");
  CHECK(unknown.messages.find("test.cga:2:9: error[E800]: unknown operation 'frobnicate'") != std::string::npos);
  const Compiled fn = compile("@StartRule\nLot --> s(geometry.groups(), 1, 1) X.\n");
  CHECK(fn.messages.find("test.cga:2:11: error[E801]: the function 'geometry.groups'") != std::string::npos);
  const Compiled faces = compile("@StartRule\nLot --> s(geometry.area(top), 1, 1) X.\n");
  CHECK(faces.messages.find("E801") != std::string::npos);
  CHECK(faces.messages.find("with a selector of faces") != std::string::npos);
  // `style Default` names the file's own style; another style redefines rules, attrs and
  // functions (test_cga_styles.cpp, tests/cga/corpus/155_style_rules*).
  CHECK(compile("style Default\n@StartRule\nLot --> X.\n").ok);
  CHECK(compile("@StartRule\nLot --> X.\nstyle Night extends Default\nLot --> Y.\nf = 2\n").ok);
  const Compiled setting = compile("nope.width = 3\n@StartRule\nLot --> X.\n");
  CHECK(setting.messages.find("test.cga:1:1: error[E010]: 'nope.width' sets an attr of an import") !=
        std::string::npos);
  // Overhangs, the ridge index and horizontal/nutant faces run (issue #44); even roofs not yet.
  CHECK(compile("@StartRule\nLot --> roofGable(30, 1, 0.5) A.\n").ok);
  CHECK(compile("@StartRule\nLot --> extrude(3) comp(f) { horizontal : A. | nutant : B. }\n").ok);
  const Compiled even = compile("@StartRule\nLot --> roofHip(30, 1, true)\n");
  CHECK(even.messages.find("test.cga:2:24: error[E801]: roofHip's even roof") != std::string::npos);
  CHECK(compile("@StartRule\nLot --> roofGable(30, 1, 1, false, 2) A.\n").ok);
  const Compiled many = compile("@StartRule\nLot --> roofHip(30, 1, false, 3)\n");
  CHECK(many.messages.find("error[E016]: 'roofHip' takes an angle, overhang and even, got 4") != std::string::npos);
  // comp's selectors of issue #44 (border, inside, world.*, object.*, street.*, an index,
  // comp(f)'s, comp(e)'s and comp(v)'s `=`) run; a fractional index is E801 where written, a
  // merged part of fgsg's edge comps (Comp("edges")) E028.
  CHECK(compile("@StartRule\nLot --> extrude(3) comp(e) { border : A. | world.up : B. | 2 : C. | -1 : D. }\n").ok);
  CHECK(compile("@StartRule\nLot --> extrude(3) comp(v) { top : A. | object.side : B. | inside : C. }\n").ok);
  CHECK(compile("@StartRule\nLot --> extrude(3) comp(f) { world.north : A. | 0 : B. | border : C. }\n").ok);
  CHECK(compile("@StartRule\nLot --> extrude(3) comp(f) { street.front : A. | street.side : B. }\n").ok);
  CHECK(compile("@StartRule\nLot --> comp(e) { street.back = A. | street.left : B. | all = C. }\n").ok);
  CHECK(compile("Lot ~> Comp(\"e\"){ streetSide=: A | all: B };", "test.fgsg").ok);
  CHECK(compile("Lot ~> Comp(\"f\"){ side=: A | top: B };", "test.fgsg").ok);
  CHECK(compile("@StartRule\nLot --> extrude(3) comp(f) { side = A. | top : B. }\n").ok);
  const Compiled edgesMerged = compile("Lot ~> Comp(\"edges\"){ eave=: A };", "test.fgsg");
  CHECK(edgesMerged.messages.find("test.fgsg:1:23: error[E028]: a merged part 'eave=:'") != std::string::npos);
  const Compiled edges = compile("@StartRule\nLot --> extrude(3) comp(e) { 1.5 : A }\n");
  CHECK(edges.messages.find("test.cga:2:30: error[E801]: the comp(e) selector '1.5'") != std::string::npos);
  CHECK(compile("@StartRule\nLot --> extrude(3) comp(v) { top = A. }\n").ok);
  const Compiled vertexLabel = compile("Lot ~> Comp(\"v\"){ eave: A };", "test.fgsg");
  CHECK(vertexLabel.messages.find("test.fgsg:1:19: error[E028]: unknown vertex 'eave:'") != std::string::npos);
  CHECK(compile("Lot ~> Comp(\"v\"){ worldUp: A | 3: B | border: C };", "test.fgsg").ok);
  const Compiled syntax = compile("@StartRule\nLot --> extrude(3\nA --> B\n");
  CHECK(syntax.messages.find("E002") != std::string::npos);
}

TEST_CASE("the primitives take CityEngine's argument forms in both dialects", "[cga][dialect]") {
  // op_primitive*: (), (sides) and (sides, radius, height) for the cylinder; (), (sides,
  // divisions) and (sides, divisions, radius) for the sphere; (width, length) for the quad.
  CHECK(compile("@StartRule\nLot --> primitiveCylinder() A.\n").ok);
  CHECK(compile("@StartRule\nLot --> primitiveCylinder(8) A.\n").ok);
  CHECK(compile("@StartRule\nLot --> primitiveSphere(8, 4, 2) A.\n").ok);
  const Compiled cylinder = compile("@StartRule\nLot --> primitiveCylinder(8, 2) A.\n");
  CHECK_FALSE(cylinder.ok);
  CHECK(cylinder.messages.find("test.cga:2:9: error[E016]: 'primitiveCylinder' takes 0, 1 or 3 arguments, got 2") !=
        std::string::npos);
  const Compiled sphere = compile("@StartRule\nLot --> primitiveSphere(8) A.\n");
  CHECK(sphere.messages.find("error[E016]: 'primitiveSphere' takes 0, 2 or 3 arguments, got 1") != std::string::npos);
  const Compiled quad = compile("Lot ~> S(4, 0, 4) PrimitiveQuad(2) A;", "test.fgsg");
  CHECK_FALSE(quad.ok);
  CHECK(quad.messages.find("test.fgsg:1:19: error[E016]: 'PrimitiveQuad' takes 0 or 2 arguments, got 1") !=
        std::string::npos);
  CHECK(compile("Lot ~> S(4, 0, 4) PrimitiveDisk(8) A;", "test.fgsg").ok);
}

TEST_CASE("CityEngine operations in the fgsg dialect are errors, and CGA files get a hint", "[cga][dialect]") {
  const Compiled color = compile("Lot ~> S(1, 1, 1) color(\"#f00\") I(\"cube\");", "test.fgsg");
  CHECK_FALSE(color.ok);
  CHECK(color.messages.find("test.fgsg:1:19: error[E800]: unknown operation 'color'") != std::string::npos);
  const Compiled rotate = compile("Lot ~> S(1, 1, 1) rotateScope I(\"cube\");", "test.fgsg");
  CHECK(rotate.messages.find("W800") != std::string::npos);
  // The grammar's own symbol of that name is fine.
  CHECK(compile("Lot ~> taper(1);\ntaper(n) ~> S(n, 1, 1) I(\"cube\");", "test.fgsg").ok);
  const Compiled cga = compile("@StartRule\nLot --> extrude(10)\n", "test.fgsg");
  CHECK_FALSE(cga.ok);
  CHECK(cga.messages.find("this looks like CityEngine CGA: name the file .cga") != std::string::npos);
}

TEST_CASE("a CGA file imports another, and an fgsg grammar imports a CGA file", "[cga][dialect]") {
  // The modules' files are written beside each other in a temporary folder.
  const std::string dir = "/tmp/fgsg_cga_import_test";
  std::system(("mkdir -p " + dir).c_str());
  {
    FILE* f = std::fopen((dir + "/facade.cga").c_str(), "w");
    std::fputs("attr floor = 3\nFacade --> split(y) { ~floor : Floor. }*\n", f);
    std::fclose(f);
  }
  const Compiled c = compile("import facade : \"facade.cga\"\n@StartRule\nLot --> s(10, facade.floor * 3, 0) facade.Facade\n",
                             dir + "/main.cga");
  INFO(c.messages);
  CHECK(c.ok);
  CHECK(c.module.findAttr("facade.floor") >= 0);
  CHECK(c.module.findSymbol("facade.Facade") >= 0);
  const Compiled g = compile("import \"facade.cga\" as f;\naxiom: S(10, 9, 0) f.Facade;\n", dir + "/main.fgsg");
  INFO(g.messages);
  CHECK(g.ok);
}

TEST_CASE("a rule of operations only is a leaf, with no W001", "[cga][dialect]") {
  // `Wall --> color(...)` outputs Wall's own geometry (the translator's leaf 'Wall.'):
  // CityEngine's everyday idiom, not a slip for the rule Wall.
  const Compiled ops = compile(
      "Lot --> extrude(3) comp(f) { side : Wall | top : Roof }\n"
      "Wall --> color(\"#ff0000\")\n"
      "Roof --> color(\"#00ff00\") Tile.\n");
  REQUIRE(ops.ok);
  CHECK(ops.messages.find("W001") == std::string::npos);
  // A leaf one slip from a rule's name is still pointed out.
  const Compiled slip = compile(
      "Lot --> extrude(3) comp(f) { side : Wal. | top : Roof. }\n"
      "Wall --> color(\"#ff0000\")\n");
  REQUIRE(slip.ok);
  CHECK(slip.messages.find("test.cga:1:37: warning[W001]: 'Wal' has no rule") != std::string::npos);
}

TEST_CASE("context queries: label() and the occlusion and context queries, in both dialects", "[cga][dialect]") {
  // The target keyword becomes its word, a missing label "" and a missing target "all".
  const Compiled cga = compile(
      "version \"2023.0\"\nb(x) = case x : 1 else : 0\n"
      "Lot --> label(\"tower\") report(\"t\", b(touches(intra, \"tower\"))) "
      "report(\"d\", minimumDistance(inter, \"tower\")) report(\"i\", b(inside())) X.\n");
  REQUIRE(cga.ok);
  const std::string printed = ir::printModule(cga.module);
  CHECK(printed.find("label \"tower\"") != std::string::npos);
  CHECK(printed.find("Shape.touches(\"intra\", \"tower\")") != std::string::npos);
  CHECK(printed.find("Shape.minimumDistance(\"inter\", \"tower\")") != std::string::npos);
  CHECK(printed.find("Shape.inside(\"all\", \"\")") != std::string::npos);
  const Compiled target = compile("version \"2023.0\"\nLot --> case inside(near, \"x\") : A.\n else : B.\n");
  CHECK(target.messages.find("test.cga:2:21: error[E016]: the target of 'inside' is intra, inter or all, not 'near'") !=
        std::string::npos);
  const Compiled count = compile("version \"2023.0\"\nLot --> report(\"d\", minimumDistance(intra)) X.\n");
  CHECK(count.messages.find("error[E016]: 'minimumDistance' takes 2 arguments") != std::string::npos);
  // contextCompare runs (test_cga_envelope_dialect.cpp); its comparison is not optional.
  CHECK(compile("version \"2023.0\"\nLot --> report(\"d\", contextCompare(intra, \"x\")) X.\n")
            .messages.find("test.cga:2:21: error[E016]: 'contextCompare' takes 3 arguments") != std::string::npos);
  // fgsg's spelling.
  const Compiled fgsg = compile(
      "axiom: A;\nA ~> Label(\"t\") Report(\"c\", Shape.contextCount(\"all\", \"t\")) "
      "Report(\"o\", Shape.overlaps(\"intra\") ? 1 : 0);\n", "test.fgsg");
  CHECK(fgsg.ok);
  const Compiled bad = compile("axiom: A;\nA ~> Report(\"x\", Shape.overlaps(\"next\", \"t\") ? 1 : 0) Label(3);\n", "test.fgsg");
  CHECK(bad.messages.find("test.fgsg:2:18: error[E025]: the target of 'Shape.overlaps' is the constant") != std::string::npos);
  CHECK(bad.messages.find("test.fgsg:2:61: error[E013]: the label of 'Label' must be a string") != std::string::npos);
}

TEST_CASE("trim() and the trim attribute translate, and their misuse is located", "[cga][dialect][trim]") {
  const Compiled ok = compile(
      "@StartRule\nLot --> extrude(10) comp(f) { side : Wall }\n"
      "Wall --> set(trim.horizontal, true) set(trim.vertical, false) s(1, 1, 1) primitiveCube() trim() X.\n");
  INFO(ok.messages);
  REQUIRE(ok.ok);
  const std::string printed = ir::printModule(ok.module);
  CHECK(printed.find("shape-operation \"SetTrim\" 0, 1") != std::string::npos);  // horizontal on
  CHECK(printed.find("shape-operation \"SetTrim\" 1, 0") != std::string::npos);  // vertical off
  CHECK(printed.find("shape-operation \"ApplyTrimPlanes\"\n") != std::string::npos);
  CHECK(compile("@StartRule\nLot --> trim(1)\n").messages.find("test.cga:2:9: error[E016]: 'trim' takes 0 arguments, got 1") !=
        std::string::npos);
  CHECK(compile("@StartRule\nLot --> set(trim.diagonal, true) X.\n")
            .messages.find("test.cga:2:13: error[E801]: set(trim.diagonal, ...)") != std::string::npos);
  CHECK(compile("@StartRule\nLot --> s(trim.vertical, 1, 1) X.\n")
            .messages.find("test.cga:2:11: error[E801]: the shape attribute 'trim.vertical'") != std::string::npos);
  CHECK(compile("axiom: Lot;\nLot ~> SetTrim(\"diagonal\", 1) X;\n", "test.fgsg")
            .messages.find("test.fgsg:2:16: error[E028]: 'SetTrim' takes horizontal, vertical here, not \"diagonal\"") !=
        std::string::npos);
  CHECK(compile("axiom: Lot;\nLot ~> ApplyTrimPlanes(1) X;\n", "test.fgsg")
            .messages.find("test.fgsg:2:8: error[E016]: 'ApplyTrimPlanes' takes 0 arguments, got 1") != std::string::npos);
}

TEST_CASE("case cond && p(x): the rest of the chain is translated once per case and not twice", "[cga][dialect]") {
  // Each such case used to translate the rest both where the chance fails and where cond
  // does: 2^n rules. Now a case adds two rules (the chance, and cond failing) and a helper.
  const int cases = 12;
  std::string text = "@StartRule\nLot --> split(x) { 1 : P }*\nP -->\n";
  for (int k = 0; k < cases; ++k)
    text += "  case scope.tx > " + std::to_string(k) + " && p(0.5) : extrude(" + std::to_string(k + 1) + ") X" +
            std::to_string(k) + ".\n";
  text += "  else : Y.\n";
  const Compiled c = compile(text);
  INFO(c.messages);
  REQUIRE(c.ok);
  CHECK(c.module.rules.size() <= size_t(3 * cases + 6));
}
