// Parser tests: source text -> AST (frontend/parse.h) and syntax diagnostics.
// The AST is compared through a compact text form (dump() below) so that each test
// states the whole expected structure in one line.
#include <catch2/catch.hpp>

#include "frontend/parse.h"
#include "frontend/statement_reuse.h"

#include <sstream>
#include <string>

using namespace fgsg::frontend;

namespace {

// ------------------------------------------------------------------ AST dump

std::string dump(const Expr* e) {
  if (!e) return "null";
  std::ostringstream out;
  auto list = [&](const char* head) {
    out << '(' << head;
    for (const auto& a : e->args) out << ' ' << dump(a.get());
    out << ')';
  };
  switch (e->kind) {
    case ExprKind::Number: out << e->number; break;
    case ExprKind::Bool: out << (e->boolean ? "true" : "false"); break;
    case ExprKind::String: out << '"' << e->text << '"'; break;
    case ExprKind::Ident: out << e->text; break;
    case ExprKind::Unary:
    case ExprKind::Binary: list(e->text.c_str()); break;
    case ExprKind::Ternary: list("?"); break;
    case ExprKind::Call: list(("call " + e->text).c_str()); break;
    case ExprKind::Member:
      list((". " + e->object + ' ' + e->text + (e->hasCall ? " call" : "")).c_str());
      break;
    case ExprKind::Vector: list("vec"); break;
    case ExprKind::RelSize: out << e->number << 'r'; break;
    case ExprKind::FloatSize: list("~"); break;
  }
  return out.str();
}
std::string dump(const ExprPtr& e) { return dump(e.get()); }

std::string dump(const Successor& s);

std::string dump(const Item& item) {
  if (item.kind == ItemKind::Bracket) {
    std::string out = "[";
    for (const auto& c : item.children) (out += ' ') += dump(c);
    return out += " ]";
  }
  std::string out = item.name;
  if (!item.args.empty()) {
    out += "(";
    for (size_t i = 0; i < item.args.size(); ++i) (out += i ? ", " : "") += dump(item.args[i]);
    out += ")";
  }
  if (item.hasBody) {
    out += "{ ";
    for (size_t i = 0; i < item.body.size(); ++i) (out += i ? " | " : "") += dump(item.body[i]);
    out += " }";
  }
  return out;
}

std::string dump(const Successor& s) {
  if (s.epsilon) return "ε";
  std::string out;
  for (size_t i = 0; i < s.items.size(); ++i) (out += i ? " " : "") += dump(s.items[i]);
  return out;
}

std::string dump(const ModulePattern& m) {
  std::string out = m.name;
  if (!m.params.empty()) {
    out += "(";
    for (size_t i = 0; i < m.params.size(); ++i) (out += i ? ", " : "") += m.params[i].name;
    out += ")";
  }
  return out;
}

// `label: left < pred > right : guard ~> succ : prob ~> succ`
std::string dump(const Rule& r) {
  std::string out;
  if (!r.label.empty()) (out += r.label) += ": ";
  for (const auto& m : r.leftContext) (out += dump(m)) += ' ';
  if (!r.leftContext.empty()) out += "< ";
  out += dump(r.predecessor);
  if (!r.rightContext.empty()) {
    out += " >";
    for (const auto& m : r.rightContext) (out += ' ') += dump(m);
  }
  if (r.guard) (out += " : ") += dump(r.guard);
  for (const auto& b : r.branches) {
    (out += " ~> ") += dump(b.successor);
    if (b.probability) (out += " : ") += dump(b.probability);
  }
  return out;
}

// ------------------------------------------------------------------ harness

struct Parsed {
  bool ok = false;
  Program program;
  std::vector<Diagnostic> diagnostics;
  std::string printed;  // Diagnostics::print output

  std::vector<std::string> rules() const {
    std::vector<std::string> out;
    for (const Rule& r : program.rules) out.push_back(dump(r));
    return out;
  }
};

Parsed parse(const std::string& text) {
  SourceFile file = SourceFile::make("test.fgsg", text);
  Diagnostics diags(&file);
  Parsed p;
  p.ok = parseProgram(file, p.program, diags);
  p.diagnostics = diags.all();
  std::ostringstream out;
  diags.print(out);
  p.printed = out.str();
  return p;
}

// Parses a program that must be free of errors.
Parsed parseOk(const std::string& text) {
  Parsed p = parse(text);
  INFO(p.printed);
  REQUIRE(p.ok);
  REQUIRE(p.diagnostics.empty());
  return p;
}

std::string onlyRule(const std::string& text) {
  Parsed p = parseOk(text);
  REQUIRE(p.program.rules.size() == 1);
  return dump(p.program.rules[0]);
}

std::string constValue(const std::string& exprText) {
  Parsed p = parseOk("const c = " + exprText + ";");
  REQUIRE(p.program.values.size() == 1);
  return dump(p.program.values[0].value);
}

}  // namespace

// ====================================================================== lexing

TEST_CASE("numbers, strings, identifiers and comments", "[parse][lex]") {
  CHECK(constValue("3") == "3");
  CHECK(constValue("0.5") == "0.5");
  CHECK(constValue("1e-3") == "0.001");
  CHECK(constValue(".5") == "0.5");
  CHECK(constValue("2.5E2") == "250");
  CHECK(constValue("\"a \\\"quoted\\\" word\"") == "\"a \"quoted\" word\"");
  CHECK(constValue("pi") == "pi");
  CHECK(constValue("\u03C0") == "pi");  // π as printed in the papers
  CHECK(constValue("true") == "true");
  CHECK(constValue("h\u00F6he_2") == "h\u00F6he_2");  // unicode letters in names

  Parsed p = parseOk("// line comment\nconst a = 1; /* block\n comment */ const b = /* inline */ 2;\n");
  REQUIRE(p.program.values.size() == 2);
  CHECK(p.program.values[1].name == "b");
  CHECK(dump(p.program.values[1].value) == "2");
}

TEST_CASE("a UTF-8 byte order mark and CRLF line ends are whitespace", "[parse][lex]") {
  Parsed p = parseOk("\xEF\xBB\xBF" "A ~> B;\r\nC ~> D\r\n");
  CHECK(p.rules() == std::vector<std::string>{"A ~> B", "C ~> D"});
  CHECK(p.program.rules[1].range.begin.line == 2);
  CHECK(p.program.rules[1].range.begin.col == 1);
}

// ================================================================ declarations

TEST_CASE("const and attr declarations", "[parse][decl]") {
  Parsed p = parseOk("const maxBranches = 4;\nattr height = 12 * 2;");
  REQUIRE(p.program.values.size() == 2);
  CHECK_FALSE(p.program.values[0].isAttr);
  CHECK(p.program.values[0].name == "maxBranches");
  CHECK(dump(p.program.values[0].value) == "4");
  CHECK(p.program.values[1].isAttr);
  CHECK(p.program.values[1].name == "height");
  CHECK(dump(p.program.values[1].value) == "(* 12 2)");
  CHECK(p.program.values[1].range.begin.line == 2);
  CHECK(p.program.values[1].range.begin.col == 1);
  CHECK(p.program.values[1].range.end.col == 21);
}

TEST_CASE("surface declarations", "[parse][decl]") {
  Parsed p = parseOk("surface \"bunny.off\";\nsurface torus(2, 0.6);");
  REQUIRE(p.program.surfaces.size() == 2);
  CHECK(p.program.surfaces[0].path == "bunny.off");
  CHECK(p.program.surfaces[0].generator.empty());
  CHECK(p.program.surfaces[1].path.empty());
  CHECK(p.program.surfaces[1].generator == "torus");
  REQUIRE(p.program.surfaces[1].args.size() == 2);
  CHECK(dump(p.program.surfaces[1].args[1]) == "0.6");
}

TEST_CASE("field declarations: file, design, curvature, call", "[parse][decl]") {
  Parsed p = parseOk(
      "field F1 = tensor(\"foot.tfield\");\n"
      "field F2 = design tensor { center at vertex 120; wedge at (0.2,0.1,0.9) decay 2; smooth 300; };\n"
      "field K = curvature;\n"
      "field V = vector(\"flow.vfield\");\n"
      "field W = blend(F1, K);\n");
  const auto& f = p.program.fields;
  REQUIRE(f.size() == 5);

  CHECK(f[0].name == "F1");
  CHECK(f[0].source == "file");
  CHECK(f[0].function == "tensor");
  CHECK(f[0].path == "foot.tfield");

  CHECK(f[1].source == "design");
  CHECK(f[1].function == "tensor");
  REQUIRE(f[1].design.size() == 3);
  const FieldDesignItem& center = f[1].design[0];
  CHECK(center.kind == "center");
  REQUIRE(center.words.size() == 2);
  CHECK(center.words[0].keyword == "at");
  CHECK(center.words[0].value == nullptr);
  CHECK(center.words[1].keyword == "vertex");
  CHECK(dump(center.words[1].value) == "120");
  const FieldDesignItem& wedge = f[1].design[1];
  CHECK(wedge.kind == "wedge");
  REQUIRE(wedge.words.size() == 2);
  CHECK(wedge.words[0].keyword == "at");
  CHECK(dump(wedge.words[0].value) == "(vec 0.2 0.1 0.9)");
  CHECK(wedge.words[1].keyword == "decay");
  CHECK(dump(wedge.words[1].value) == "2");
  const FieldDesignItem& smooth = f[1].design[2];
  CHECK(smooth.kind == "smooth");
  REQUIRE(smooth.words.size() == 1);
  CHECK(smooth.words[0].keyword.empty());
  CHECK(dump(smooth.words[0].value) == "300");

  CHECK(f[2].source == "curvature");
  CHECK(f[3].source == "file");
  CHECK(f[3].function == "vector");
  CHECK(f[4].source == "call");
  CHECK(f[4].function == "blend");
  CHECK(f[4].args.size() == 2);
}

TEST_CASE("texture, derive, turtle, axiom declarations", "[parse][decl]") {
  Parsed p = parseOk(
      "texture mask = \"paint.png\";\n"
      "derive parallel 5; derive depthfirst; derive breadthfirst;\n"
      "turtle angle 60 step 1 width 0.05;\n"
      "axiom: S(20,0,12) footprint;\n");
  REQUIRE(p.program.textures.size() == 1);
  CHECK(p.program.textures[0].name == "mask");
  CHECK(p.program.textures[0].path == "paint.png");

  REQUIRE(p.program.derives.size() == 3);
  CHECK(p.program.derives[0].mode == "parallel");
  CHECK(dump(p.program.derives[0].steps) == "5");
  CHECK(p.program.derives[1].mode == "depthfirst");
  CHECK(p.program.derives[1].steps == nullptr);
  CHECK(p.program.derives[2].mode == "breadthfirst");

  REQUIRE(p.program.turtles.size() == 1);
  const auto& settings = p.program.turtles[0].settings;
  REQUIRE(settings.size() == 3);
  CHECK(settings[0].first == "angle");
  CHECK(dump(settings[0].second) == "60");
  CHECK(settings[2].first == "width");
  CHECK(dump(settings[2].second) == "0.05");

  REQUIRE(p.program.axioms.size() == 1);
  CHECK(dump(p.program.axioms[0].successor) == "S(20, 0, 12) footprint");
}

TEST_CASE("collision declarations: words and radii", "[parse][decl]") {
  Parsed p = parseOk(
      "collision all;\n"
      "collision mesh;\n"
      "collision centre 0.3;\n"
      "collision all center .25;\n"
      "collision geodesic -2 all;\n"
      "collision;\n");
  const auto& c = p.program.collisions;
  REQUIRE(c.size() == 6);
  auto words = [](const CollisionDecl& d) {
    std::string out;
    for (const auto& w : d.words) {
      std::ostringstream n;
      n << w.number;
      (out += out.empty() ? "" : " ") += w.isNumber() ? "#" + n.str() : w.word;
    }
    return out;
  };
  CHECK(words(c[0]) == "all");
  CHECK(words(c[1]) == "mesh");
  CHECK(words(c[2]) == "centre #0.3");
  CHECK(words(c[3]) == "all center #0.25");
  CHECK(words(c[4]) == "geodesic #-2 all");  // the sign is kept for sema to reject
  CHECK(words(c[5]).empty());
  // Ranges: the declaration from its keyword; a signed number from its '-'.
  CHECK(c[3].range.begin.line == 4);
  CHECK(c[3].range.begin.col == 1);
  CHECK(c[3].words[2].range.begin.col == 22);
  CHECK(c[4].words[1].range.begin.col == 20);
  CHECK(c[4].words[1].range.end.col == 21);
}

TEST_CASE("collision is a keyword: it starts a statement and is no name", "[parse][decl]") {
  // Without ';' the line break ends the rule before it and the declaration before the next.
  Parsed p = parseOk("Axiom ~> A\ncollision all centre 0.5\nA ~> I(\"cube\")\n");
  CHECK(p.rules() == std::vector<std::string>{"Axiom ~> A", "A ~> I(\"cube\")"});
  REQUIRE(p.program.collisions.size() == 1);
  CHECK(p.program.collisions[0].words.size() == 3);

  Parsed bad = parse("collision ~> A;");
  CHECK_FALSE(bad.ok);
  Parsed call = parse("collision centre(0.3);");
  REQUIRE(call.diagnostics.size() == 1);
  CHECK(call.diagnostics[0].code == "E002");
  CHECK(call.diagnostics[0].range.begin.col == 17);
  CHECK(call.diagnostics[0].message ==
        "expected a collision setting (all, mesh, centre R, geodesic R, distance D) or ';' after "
        "'collision centre', found '('");
}

TEST_CASE("priority headers set the priority of the rules that follow", "[parse][decl]") {
  Parsed p = parseOk("A ~> B;\nPRIORITY 1:\nC ~> D;\nE ~> F;\npriority 3:\nG ~> H;\n");
  REQUIRE(p.program.rules.size() == 4);
  CHECK(p.program.rules[0].priority == 0);
  CHECK(p.program.rules[1].priority == 1);
  CHECK(p.program.rules[2].priority == 1);
  CHECK(p.program.rules[3].priority == 3);
}

// ======================================================================= rules

TEST_CASE("every arrow spelling", "[parse][rule]") {
  CHECK(onlyRule("A ~> B;") == "A ~> B");
  CHECK(onlyRule("A -> B;") == "A ~> B");
  CHECK(onlyRule("A = B;") == "A ~> B");
  CHECK(onlyRule("A \u2192 B;") == "A ~> B");  // →
  CHECK(onlyRule("A \u21DD B;") == "A ~> B");  // ⇝
}

TEST_CASE("labels, parameters, guards and probabilities", "[parse][rule]") {
  CHECK(onlyRule("1: A ~> B;") == "1: A ~> B");
  CHECK(onlyRule("p4: A ~> B;") == "p4: A ~> B");
  CHECK(onlyRule("F(l, w) -> F(l/3, w);") == "F(l, w) ~> F((/ l 3), w)");
  CHECK(onlyRule("A : x > 0 ~> B;") == "A : (> x 0) ~> B");
  CHECK(onlyRule("S : (F1.mincurv>=0) && (F1.maxcurv>=0) ~> I(\"e.obj\")") ==
        "S : (&& (>= (. F1 mincurv) 0) (>= (. F1 maxcurv) 0)) ~> I(\"e.obj\")");
  CHECK(onlyRule("1: S : cond ~> B;") == "1: S : cond ~> B");
  CHECK(onlyRule("C = [ RS(90) A ] : 0.2;") == "C ~> [ RS(90) A ] : 0.2");
  CHECK(onlyRule("A ~> B : 0.3 ~> C : 0.7;") == "A ~> B : 0.3 ~> C : 0.7");
}

TEST_CASE("label or predecessor: `X : Y ~> Z` reads X as the label", "[parse][rule]") {
  CHECK(onlyRule("X : Y ~> Z;") == "X: Y ~> Z");
  CHECK(onlyRule("X : Y(n) ~> Z;") == "X: Y(n) ~> Z");
  // Anything else after the colon is a guard.
  CHECK(onlyRule("X : y + 1 ~> Z;") == "X : (+ y 1) ~> Z");
  CHECK(onlyRule("X : f(1) > 0 ~> Z;") == "X : (> (call f 1) 0) ~> Z");
}

TEST_CASE("ABOP contexts", "[parse][rule]") {
  CHECK(onlyRule("A(x) < B(y) > C : x < y -> B(y+1);") == "A(x) < B(y) > C : (< x y) ~> B((+ y 1))");
  CHECK(onlyRule("A < B > C ~> D;") == "A < B > C ~> D");
  CHECK(onlyRule("A > B ~> C;") == "A > B ~> C");
  CHECK(onlyRule("A B < C ~> D;") == "A B < C ~> D");
  CHECK(onlyRule("A(x) < B(y) > C(z) ~> D;") == "A(x) < B(y) > C(z) ~> D");

  Parsed p = parseOk("B > [ C ] D ~> E;");
  const Rule& r = p.program.rules[0];
  REQUIRE(r.rightContext.size() == 4);
  CHECK(r.rightContext[0].name == "[");
  CHECK(r.rightContext[1].name == "C");
  CHECK(r.rightContext[2].name == "]");
  CHECK(r.rightContext[3].name == "D");
}

TEST_CASE("Müller's guarded form: a non-successor after the first arrow is the guard", "[parse][rule]") {
  CHECK(onlyRule("facade ~> Shape.visible(\"street\") ~> Subdiv(\"X\",1r,door_width*1.5){ tiles | entrance } : 0.5"
                 " ~> Subdiv(\"X\",door_width*1.5,1r){ entrance | tiles } : 0.5;") ==
        "facade : (. Shape visible call \"street\") ~> Subdiv(\"X\", 1r, (* door_width 1.5)){ tiles | entrance } : 0.5"
        " ~> Subdiv(\"X\", (* door_width 1.5), 1r){ entrance | tiles } : 0.5");
  CHECK(onlyRule("window ~> Scope.occ(\"noparent\") != \"none\" ~> wall;") ==
        "window : (!= (. Scope occ call \"noparent\") \"none\") ~> wall");
  // When the first part is a successor, every part is a branch.
  CHECK(onlyRule("A ~> B ~> C;") == "A ~> B ~> C");
  CHECK(onlyRule("A ~> B(1) C ~> D;") == "A ~> B(1) C ~> D");
}

TEST_CASE("the ',' after a rule may be left out at the end of a line", "[parse][rule]") {
  Parsed fig1 = parseOk(
      "start = S(0.5, 0.5, 0.5) F\n"
      "F = [ RS(Rand(-5, 5)) T(Rand(0.6, 0.65), 0, 0) M C z ] F ;\n"
      "A = RS(Rand(-5, 5)) T(Rand(0.6, 0.65), 0, 0) M C z\n"
      "C = [ RS(90) A ] : 0.2;\n"
      "C = RS(-3) M A :\n"
      "    0.1;\n"
      "D = E\n");
  CHECK(fig1.rules() == std::vector<std::string>{
                            "start ~> S(0.5, 0.5, 0.5) F",
                            "F ~> [ RS((call Rand (- 5) 5)) T((call Rand 0.6 0.65), 0, 0) M C z ] F",
                            "A ~> RS((call Rand (- 5) 5)) T((call Rand 0.6 0.65), 0, 0) M C z",
                            "C ~> [ RS(90) A ] : 0.2",
                            "C ~> RS((- 3)) M A : 0.1",
                            "D ~> E",
                        });
  CHECK(fig1.program.rules[0].range.begin.line == 1);
  CHECK(fig1.program.rules[0].range.end.line == 1);
  CHECK(fig1.program.rules[0].range.end.col == 26);
  CHECK(fig1.program.rules[4].range.end.line == 6);

  // A successor continued on the next line, Müller branches on their own lines, labels.
  Parsed more = parseOk(
      "lot ~> S(1r, 12, 1r)\n"
      "       building\n"
      "facade ~> Shape.visible(\"street\")\n"
      "       ~> A : 0.5\n"
      "       ~> B : 0.5\n"
      "1: X ~> Y\n"
      "p2: Y ~> Z\n"
      "axiom: F(1)\n"
      "F(l) -> F(l/2)\n"
      "const k = 2\n"
      "A < B ~> C\n");
  CHECK(more.rules() == std::vector<std::string>{
                            "lot ~> S(1r, 12, 1r) building",
                            "facade : (. Shape visible call \"street\") ~> A : 0.5 ~> B : 0.5",
                            "1: X ~> Y",
                            "p2: Y ~> Z",
                            "F(l) ~> F((/ l 2))",
                            "A < B ~> C",
                        });
  REQUIRE(more.program.axioms.size() == 1);
  CHECK(dump(more.program.axioms[0].successor) == "F(1)");
  REQUIRE(more.program.values.size() == 1);
}

// ================================================================== successors

TEST_CASE("successor items: calls, bodies, brackets, turtle symbols", "[parse][successor]") {
  CHECK(onlyRule("A ~> Lock{ B | C };") == "A ~> Lock{ B | C }");
  CHECK(onlyRule("A ~> Marching(0.1, 30, c){ Top, Extruded } Branch(2){ A, B };") ==
        "A ~> Marching(0.1, 30, c){ Top | Extruded } Branch(2){ A | B }");
  CHECK(onlyRule("A ~> Subdiv(\"X\",1r,window_width,1r){ wall | Subdiv(\"Y\",2r,window_height,1r){ wall | window | wall } | wall };") ==
        "A ~> Subdiv(\"X\", 1r, window_width, 1r){ wall | Subdiv(\"Y\", 2r, window_height, 1r){ wall | window | wall } | wall }");
  CHECK(onlyRule("A ~> Subdiv(\"X\",flatbrick_width,1r){ \u03B5 | Repeat(\"X\",flatbrick_width){ roofedge } };") ==
        "A ~> Subdiv(\"X\", flatbrick_width, 1r){ ε | Repeat(\"X\", flatbrick_width){ roofedge } }");
  CHECK(onlyRule("A ~> [ B [ C ] ] D;") == "A ~> [ B [ C ] ] D");
  CHECK(onlyRule("A ~> + - & ^ \\ / | ! $ % F;") == "A ~> + - & ^ \\ / | ! $ % F");
  CHECK(onlyRule("A ~> +(30) !(0.5) F(1);") == "A ~> +(30) !(0.5) F(1)");
  CHECK(onlyRule("A ~> F&&F||F;") == "A ~> F & & F | | F");
  // '|' separates body parts at the top of a body, but is a turtle symbol inside [ ].
  CHECK(onlyRule("A ~> X{ [ B | C ] | D };") == "A ~> X{ [ B | C ] | D }");

  Parsed p = parseOk("A ~> + F;");
  const Item& plus = p.program.rules[0].branches[0].successor.items[0];
  CHECK(plus.kind == ItemKind::Turtle);
  CHECK(plus.name == "+");
  const Item& f = p.program.rules[0].branches[0].successor.items[1];
  CHECK(f.kind == ItemKind::Call);
  CHECK_FALSE(f.hasBody);
}

TEST_CASE("ABOP polygons: { . } items, and a name followed by a polygon", "[parse][successor]") {
  CHECK(onlyRule("A ~> [ + A { . ] . C . };") == "A ~> [ + A { . ] . C . }");
  // `B{.-f.}`: B (which takes no body), then the polygon; `|` inside it is a turtle symbol.
  CHECK(onlyRule("A ~> B{.-f.|-f.};") == "A ~> B { . - f . | - f . }");
  CHECK(onlyRule("A ~> F(2){.f.};") == "A ~> F(2) { . f . }");
  Parsed p = parseOk("A ~> L{.f.};");
  const auto& items = p.program.rules[0].branches[0].successor.items;
  REQUIRE(items.size() == 6);
  CHECK(items[0].kind == ItemKind::Call);
  CHECK_FALSE(items[0].hasBody);
  CHECK(items[1].kind == ItemKind::Turtle);
  CHECK(items[1].name == "{");
  CHECK(items[2].name == ".");
  CHECK(items[5].name == "}");
  // A '.' between two names written together is a member access; any other a vertex.
  CHECK(onlyRule("A : Scope.sx > 1 ~> B . C;") == "A : (> (. Scope sx) 1) ~> B . C");
  // Without a vertex, or for a command that takes bodies, it stays a body.
  CHECK(onlyRule("A ~> X{ B | C };") == "A ~> X{ B | C }");
  CHECK(onlyRule("A ~> Lock{ B | C };") == "A ~> Lock{ B | C }");
}

TEST_CASE("the lpfg colour step is a semicolon with more of the successor after it on its line", "[parse][successor]") {
  CHECK(onlyRule("A ~> F ; F;") == "A ~> F ' F");
  CHECK(onlyRule("A ~> F;(2) [ ; F ];") == "A ~> F '(2) [ ' F ]");
  // A ';' before a rule head or a declaration, or at the end of its line, ends the rule.
  Parsed two = parseOk("A ~> B; B ~> C;\nC ~> D ;\nD ~> E; derive parallel 2;");
  REQUIRE(two.program.rules.size() == 4);
  CHECK(dump(two.program.rules[0].branches[0].successor) == "B");
  CHECK(dump(two.program.rules[2].branches[0].successor) == "D");
  CHECK(dump(two.program.rules[3].branches[0].successor) == "E");
  Parsed axiom = parseOk("axiom: F ; F;\n1: F ~> F F;");
  REQUIRE(axiom.program.axioms.size() == 1);
  CHECK(dump(axiom.program.axioms[0].successor) == "F ' F");
  CHECK(axiom.program.rules.size() == 1);
}

TEST_CASE("an ABOP predefined surface ~name is the box at the turtle and the asset in brackets", "[parse][successor]") {
  CHECK(onlyRule("A ~> F ~leaf(2) ~\"petal.obj\";") == "A ~> F [ ~(2) I(\"leaf\") ] [ ~ I(\"petal.obj\") ]");
}

TEST_CASE("the empty successor", "[parse][successor]") {
  for (const char* spelling : {"\u03B5", "epsilon", "NIL"}) {
    Parsed p = parseOk(std::string("A ~> ") + spelling + ";");
    const Successor& s = p.program.rules[0].branches[0].successor;
    CHECK(s.epsilon);
    CHECK(s.items.empty());
  }
}

TEST_CASE("relative and floating sizes, '~>' is still the arrow", "[parse][successor]") {
  CHECK(onlyRule("A ~> S(1r, 0.5r, 2r);") == "A ~> S(1r, 0.5r, 2r)");
  CHECK(onlyRule("A~>Repeat(\"X\",~window_width){ T(~2) };") == "A ~> Repeat(\"X\", (~ window_width)){ T((~ 2)) }");
  Parsed p = parseOk("A ~> S(1r, ~2);");
  const auto& args = p.program.rules[0].branches[0].successor.items[0].args;
  CHECK(args[0]->kind == ExprKind::RelSize);
  CHECK(args[0]->number == 1.0);
  CHECK(args[1]->kind == ExprKind::FloatSize);
  CHECK(args[1]->args[0]->number == 2.0);
}

// ================================================================= expressions

TEST_CASE("expression precedence and associativity", "[parse][expr]") {
  CHECK(constValue("1 + 2 * 3") == "(+ 1 (* 2 3))");
  CHECK(constValue("1 - 2 - 3") == "(- (- 1 2) 3)");
  CHECK(constValue("2 ^ 3 ^ 2") == "(^ 2 (^ 3 2))");
  CHECK(constValue("-x ^ 2") == "(- (^ x 2))");
  CHECK(constValue("-a * b") == "(* (- a) b)");
  CHECK(constValue("a % b / c") == "(/ (% a b) c)");
  CHECK(constValue("!a || b && c") == "(|| (! a) (&& b c))");
  CHECK(constValue("a == b < c") == "(== a (< b c))");
  CHECK(constValue("a <= b != c >= d") == "(!= (<= a b) (>= c d))");
  CHECK(constValue("c ? 1 : d ? 2 : 3") == "(? c 1 (? d 2 3))");
  CHECK(constValue("a || b ? x + 1 : y") == "(? (|| a b) (+ x 1) y)");
  CHECK(constValue("(1 + 2) * 3") == "(* (+ 1 2) 3)");
  CHECK(constValue("+x") == "(+ x)");
}

TEST_CASE("calls, members, vectors", "[parse][expr]") {
  CHECK(constValue("Rand(1, 2)") == "(call Rand 1 2)");
  CHECK(constValue("sin(x) + max(a, b, c)") == "(+ (call sin x) (call max a b c))");
  CHECK(constValue("Scope.sx") == "(. Scope sx)");
  CHECK(constValue("Shape.visible(\"street\")") == "(. Shape visible call \"street\")");
  CHECK(constValue("context.mask(texCoord)") == "(. context mask call texCoord)");
  CHECK(constValue("(0.2, 0.1, 0.9)") == "(vec 0.2 0.1 0.9)");
  CHECK(constValue("(a, b)") == "(vec a b)");

  Parsed p = parseOk("const c = F1.vector1;");
  const Expr& member = *p.program.values[0].value;
  CHECK(member.kind == ExprKind::Member);
  CHECK(member.object == "F1");
  CHECK(member.text == "vector1");
  CHECK_FALSE(member.hasCall);
}

TEST_CASE("source ranges of nodes", "[parse][range]") {
  Parsed p = parseOk("\n  A ~> B(x + 1)  C;\n");
  const Rule& r = p.program.rules[0];
  CHECK(r.range.begin.line == 2);
  CHECK(r.range.begin.col == 3);
  CHECK(r.range.end.col == 19);  // the ';'
  CHECK(r.predecessor.range.begin.col == 3);
  const Item& b = r.branches[0].successor.items[0];
  CHECK(b.range.begin.col == 8);
  CHECK(b.range.end.col == 15);
  const Expr& sum = *b.args[0];
  CHECK(sum.range.begin.col == 10);
  CHECK(sum.range.end.col == 14);
  CHECK(sum.args[1]->range.begin.col == 14);
  const Item& c = r.branches[0].successor.items[1];
  CHECK(c.range.begin.col == 18);
}

// ============================================================ example programs

TEST_CASE("example: the four-rule FGSG grammar", "[parse][example]") {
  Parsed p = parseOk(
      "1: Axiom ~> P;\n"
      "2: P ~> [ Rz(30) T(0.6, 0, 0) A ] [ Rz(150) T(0.6, 0, 0) A ] [ Rz(-90) T(0.6, 0, 0) A ];\n"
      "3: A ~> B [ T(0.6, 0, 0) Rz(60) T(0.6, 0, 0) A ] [ T(0.6, 0, 0) Rz(-60) T(0.6, 0, 0) A ];\n"
      "4: B ~> S(1.0, 1.0, 0.6) I(\"torus\");\n");
  CHECK(p.rules() == std::vector<std::string>{
                         "1: Axiom ~> P",
                         "2: P ~> [ Rz(30) T(0.6, 0, 0) A ] [ Rz(150) T(0.6, 0, 0) A ] [ Rz((- 90)) T(0.6, 0, 0) A ]",
                         "3: A ~> B [ T(0.6, 0, 0) Rz(60) T(0.6, 0, 0) A ] [ T(0.6, 0, 0) Rz((- 60)) T(0.6, 0, 0) A ]",
                         "4: B ~> S(1, 1, 0.6) I(\"torus\")",
                     });
  CHECK(p.program.rules[3].range.begin.line == 4);
}

TEST_CASE("example: ABOP Koch curve", "[parse][example]") {
  Parsed p = parseOk("derive parallel 4; axiom: F(1); F(l) -> F(l/3) + F(l/3) - - F(l/3) + F(l/3);");
  REQUIRE(p.program.derives.size() == 1);
  CHECK(dump(p.program.axioms[0].successor) == "F(1)");
  CHECK(p.rules() == std::vector<std::string>{
                         "F(l) ~> F((/ l 3)) + F((/ l 3)) - - F((/ l 3)) + F((/ l 3))"});
}

TEST_CASE("example: Müller building grammar with priorities", "[parse][example]") {
  Parsed p = parseOk(
      "attr building_height = 12;\n"
      "const door_width = 1.2;\n"
      "PRIORITY 1:\n"
      "lot ~> S(1r,building_height,1r) facades\n"
      "facades ~> Comp(\"sidefaces\"){ facade }\n"
      "facade ~> Shape.visible(\"street\")\n"
      "       ~> Subdiv(\"X\",1r,door_width*1.5){ tiles | entrance } : 0.5\n"
      "       ~> Subdiv(\"X\",door_width*1.5,1r){ entrance | tiles } : 0.5\n"
      "facade ~> Repeat(\"X\",~window_width){ tile };\n"
      "tile ~> Subdiv(\"X\",1r,window_width,1r){ wall | Subdiv(\"Y\",2r,window_height,1r){ wall | window | wall } | wall }\n"
      "PRIORITY 2:\n"
      "window ~> Scope.occ(\"noparent\") != \"none\" ~> wall\n"
      "roof ~> Subdiv(\"X\",flatbrick_width,1r){ \u03B5 | Repeat(\"X\",flatbrick_width){ roofedge } };\n");
  REQUIRE(p.program.rules.size() == 7);
  CHECK(p.program.rules[0].priority == 1);
  CHECK(p.program.rules[4].priority == 1);
  CHECK(p.program.rules[5].priority == 2);
  CHECK(p.program.rules[6].priority == 2);
  CHECK(dump(p.program.rules[2]) ==
        "facade : (. Shape visible call \"street\") ~> Subdiv(\"X\", 1r, (* door_width 1.5)){ tiles | entrance } : 0.5"
        " ~> Subdiv(\"X\", (* door_width 1.5), 1r){ entrance | tiles } : 0.5");
  CHECK(p.program.rules[2].range.end.line == 8);
  CHECK(dump(p.program.rules[5]) == "window : (!= (. Scope occ call \"noparent\") \"none\") ~> wall");
}

// ================================================================ diagnostics

TEST_CASE("three syntax errors give three diagnostics at their tokens", "[parse][error]") {
  Parsed p = parse(
      "const a = 1 +;\n"
      "A ~> B(1,;\n"
      "attr = 3;\n"
      "C ~> D;\n");
  CHECK_FALSE(p.ok);
  INFO(p.printed);
  REQUIRE(p.diagnostics.size() == 3);
  for (const Diagnostic& d : p.diagnostics) {
    CHECK(d.severity == Severity::Error);
    CHECK(d.code == "E002");
  }
  CHECK(p.diagnostics[0].range.begin.line == 1);
  CHECK(p.diagnostics[0].range.begin.col == 14);
  CHECK(p.diagnostics[1].range.begin.line == 2);
  CHECK(p.diagnostics[1].range.begin.col == 10);
  CHECK(p.diagnostics[2].range.begin.line == 3);
  CHECK(p.diagnostics[2].range.begin.col == 6);
  // Parsing went on after the errors.
  CHECK(p.rules() == std::vector<std::string>{"C ~> D"});
}

TEST_CASE("syntax error messages name what was expected in words", "[parse][error]") {
  auto message = [](const std::string& text) {
    Parsed p = parse(text);
    REQUIRE(p.diagnostics.size() == 1);
    return p.diagnostics[0].message;
  };
  CHECK(message("A ~> B )") == "expected ';' or a successor after 'A ~> B', found ')'");
  CHECK(message("A ~> B(1 2);") == "expected ',' or ')' after 'A ~> B(1', found '2'");
  CHECK(message("A ~> ;") == "expected a successor after 'A ~>', found ';'");
  CHECK(message("const y = 4 attr z = 5;") == "expected ';' after 'const y = 4', found 'attr'");
  CHECK(message("A ~> B C(") == "expected an expression or ')' after 'A ~> B C(', found the end of the file");
  CHECK(message("A ~> B : ;") == "expected an expression after 'A ~> B :', found ';'");
  CHECK(message("const x = a.b.c.d;").find("found '.'") != std::string::npos);
  CHECK_THAT(message("A ~> I('cube');"), Catch::Contains("strings are written in double quotes"));
  // Never ANTLR's raw token sets.
  for (const char* bad : {"A ~> B )", "@", "const = ;", "A : ~> B;", "field F = ;", "X ~> ( )"}) {
    Parsed p = parse(bad);
    CHECK_FALSE(p.ok);
    CHECK(p.printed.find("mismatched input") == std::string::npos);
    CHECK(p.printed.find("expecting {") == std::string::npos);
  }
}

TEST_CASE("an error at the end of a line points just after its last token", "[parse][error]") {
  Parsed p = parse("A ~> B :\n");
  REQUIRE(p.diagnostics.size() == 1);
  CHECK(p.diagnostics[0].range.begin.line == 1);
  CHECK(p.diagnostics[0].range.begin.col == 9);
  CHECK(p.diagnostics[0].message == "expected an expression after 'A ~> B :', found the end of the file");
}

TEST_CASE("lexical errors are E001 and parsing goes on", "[parse][error][lex]") {
  Parsed p = parse("const x = \"abc\nA ~> B;\n@@ C ~> D;\n/* open");
  CHECK_FALSE(p.ok);
  INFO(p.printed);
  REQUIRE(p.diagnostics.size() == 3);
  CHECK(p.diagnostics[0].code == "E001");
  CHECK(p.diagnostics[0].message.find("unterminated string") != std::string::npos);
  CHECK(p.diagnostics[0].range.begin.line == 1);
  CHECK(p.diagnostics[0].range.begin.col == 11);
  CHECK(p.diagnostics[1].code == "E001");
  CHECK(p.diagnostics[1].message == "unexpected characters '@@'");
  CHECK(p.diagnostics[1].range.begin.line == 3);
  CHECK(p.diagnostics[1].range.end.col == 2);
  CHECK(p.diagnostics[2].code == "E001");
  CHECK(p.diagnostics[2].message.find("unterminated comment") != std::string::npos);
  // The unterminated string is read up to the line end; the rest still parses.
  REQUIRE(p.program.values.size() == 1);
  CHECK(dump(p.program.values[0].value) == "\"abc\"");
  CHECK(p.rules() == std::vector<std::string>{"A ~> B", "C ~> D"});
}

TEST_CASE("diagnostic format: location, code, source line, caret", "[parse][error][format]") {
  Parsed p = parse("const ok = 1;\nA ~> B )\n");
  CHECK(p.printed ==
        "test.fgsg:2:8: error[E002]: expected ';' or a successor after 'A ~> B', found ')'\n"
        "A ~> B )\n"
        "       ^\n");

  SourceFile file = SourceFile::make("f.fgsg", "x\n\tA ~>  Subdiv(\n");
  Diagnostics diags(&file);
  diags.error("E012", {{2, 8}, {2, 13}}, "unknown command");
  diags.warning("W003", {{2, 2}, {2, 2}}, "shape never derived");
  diags.note({{1, 1}, {1, 1}}, "declared here");
  diags.error("E020", {}, "no axiom");
  REQUIRE(diags.errorCount() == 2);
  CHECK(diags.format(diags.all()[0]) ==
        "f.fgsg:2:8: error[E012]: unknown command\n"
        "\tA ~>  Subdiv(\n"
        "\t      ^~~~~~");
  CHECK(diags.format(diags.all()[1]) ==
        "f.fgsg:2:2: warning[W003]: shape never derived\n"
        "\tA ~>  Subdiv(\n"
        "\t^");
  CHECK(diags.format(diags.all()[2]) == "f.fgsg:1:1: note: declared here\nx\n^");
  CHECK(diags.format(diags.all()[3]) == "f.fgsg: error[E020]: no axiom");
}

TEST_CASE("never crashes: empty, garbage, unterminated, deep nesting", "[parse][error][robust]") {
  CHECK(parse("").ok);
  CHECK(parse("   \n// only a comment\n").ok);
  CHECK(parse(";;").ok);

  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage += static_cast<char>((i * 7919 + 13) % 256);
  Parsed g = parse(garbage);
  CHECK_FALSE(g.ok);
  CHECK(g.diagnostics.size() <= 80);  // capped, not one per byte

  // Found by fuzzing: ANTLR conjured a missing ')' in front of the implicit ';'.
  Parsed conjured = parse("X~>g(A,B}[F)");
  REQUIRE(conjured.diagnostics.size() == 1);
  CHECK(conjured.diagnostics[0].message == "expected ',' or ')' after 'X~>g(A,B', found '}'");
  Parsed missingColon = parse("priority 1\nA ~> B;");
  REQUIRE(missingColon.diagnostics.size() == 1);
  CHECK(missingColon.diagnostics[0].message == "expected ':' after 'priority 1', found the end of the line");
  CHECK(missingColon.rules() == std::vector<std::string>{"A ~> B"});

  CHECK_FALSE(parse("A ~> B(\"never closed").ok);
  CHECK_FALSE(parse("A ~> B{ C | ").ok);
  CHECK_FALSE(parse("field F = design tensor { center at").ok);
  Parsed arithmetic = parse("field F = design tensor { wedge at vertex 0 decay 2 * k; };");
  REQUIRE(arithmetic.diagnostics.size() == 1);
  CHECK(arithmetic.diagnostics[0].range.begin.col == 53);
  CHECK(arithmetic.diagnostics[0].message ==
        "expected a keyword (at, decay, strength ...), a value or ';' after '...esign tensor { "
        "wedge at vertex 0 decay 2', found '*' (a design value is a number, a point, a const "
        "name or an expression in parentheses: `decay (2 * k)`)");
  CHECK(parse("field F = design tensor { wedge at vertex 0 decay (2 * k); };").ok);

  const std::string deepParens = std::string(200, '(') + "1" + std::string(200, ')');
  CHECK(parse("const x = " + deepParens + ";").ok);
  const std::string tooDeep = std::string(100000, '(') + "1" + std::string(100000, ')');
  Parsed deep = parse("const x = " + tooDeep + ";\nA ~> B;");
  CHECK_FALSE(deep.ok);
  REQUIRE(deep.diagnostics.size() == 1);
  CHECK(deep.diagnostics[0].message.find("nested too deeply") != std::string::npos);
  CHECK(deep.rules() == std::vector<std::string>{"A ~> B"});

  std::string powers = "const x = ";
  for (int i = 0; i < 50000; ++i) powers += "2^";
  CHECK_FALSE(parse(powers + "2;").ok);
  std::string brackets = "A ~> ";
  for (int i = 0; i < 50000; ++i) brackets += "[ F ";
  CHECK_FALSE(parse(brackets).ok);
  std::string sum = "const x = 1";
  for (int i = 0; i < 20000; ++i) sum += " + 1";
  CHECK_FALSE(parse(sum + ";").ok);
}

TEST_CASE("a number literal beyond a double is E002 where it stands, not a silent 0", "[parse][error]") {
  Parsed p = parse("const big = 1e400;\nA ~> S(2.5e308r, 1, 1) B;\ncollision centre 1e999;\n");
  CHECK_FALSE(p.ok);
  INFO(p.printed);
  REQUIRE(p.diagnostics.size() == 3);
  const int columns[] = {13, 8, 18};
  for (int k = 0; k < 3; ++k) {
    CHECK(p.diagnostics[k].code == "E002");
    CHECK(p.diagnostics[k].range.begin.line == k + 1);
    CHECK(p.diagnostics[k].range.begin.col == columns[k]);
  }
  CHECK(p.diagnostics[0].message == "the number 1e400 is too large (numbers are at most about 1.8e308)");
  CHECK(p.diagnostics[1].message.find("the number 2.5e308r is too large") == 0);
  // Too small is (about) zero, and the largest double is a number.
  Parsed q = parse("const tiny = 1e-400;\nconst most = 1.7976931348623157e308;\n");
  CHECK(q.ok);
  REQUIRE(q.program.values.size() == 2);
  CHECK(dump(q.program.values[0].value) == "0");
  CHECK(q.program.values[1].value->number == 1.7976931348623157e308);
}

// ============================================================= statement reuse

namespace {

// What a parse gives that later passes read: each rule and value with its place, priority
// and section, and the diagnostics as printed.
std::string programWithPlaces(const Program& p, const std::string& printed) {
  std::ostringstream out;
  auto place = [&](const SourceRange& r) {
    out << '@' << r.begin.line << ':' << r.begin.col << '-' << r.end.line << ':' << r.end.col;
  };
  for (const Rule& r : p.rules) {
    out << dump(r) << " priority " << r.priority << " section " << static_cast<int>(r.section);
    place(r.range);
    place(r.predecessor.range);
    out << '\n';
  }
  for (const ValueDecl& v : p.values) {
    out << (v.isAttr ? "attr " : "const ") << v.name << " = " << dump(v.value);
    place(v.range);
    place(v.value->range);
    out << '\n';
  }
  return out.str() + printed;
}

}  // namespace

TEST_CASE("statement reuse gives the AST of a fresh parse, edit after edit", "[parse][reuse]") {
  const std::vector<std::string> texts = {
      "attr a = 1;\nA ~> B(a);\npriority 2:\nC ~> D;\nE ~> F; G ~> H;\n",
      "attr a = 1;\nA ~> B(a + 1);\npriority 2:\nC ~> D;\nE ~> F; G ~> H;\n",  // one rule changed
      "attr a = 1;\nA ~> B(a + 1);\npriority 5:\nC ~> D;\nE ~> F; G ~> H;\n",  // the priority only
      "// new\n\nattr a = 1;\nA ~> B(a + 1);\npriority 5:\nC ~> D;\nE ~> F; G ~> H;\n",  // lines moved
      "// new\n\nattr a = 1;\nA ~> B(a + 1);\npriority 5:\nC ~> D;\nE ~> FF; G ~> H;\n",  // columns moved
      "// new\n\nattr a = 1;\nA ~> B(a + 1;\npriority 5:\nC ~> D;\nE ~> FF; G ~> H;\n",  // a syntax error
      "// new\n\nattr a = 1;\nA ~> B(a + 1;\npriority 5:\nC ~> D;\nE ~> FF; G ~> H;\n",  // the same again
      "// new\n\nattr a = 2;\nA ~> B(a + 1);\npriority 5:\nC ~> D;\nE ~> FF; G ~> H;\n",
      "attr a = 1;\nA ~> B(a);\npriority 2:\nC ~> D;\nE ~> F; G ~> H;\n",  // back to the first
  };
  // The statements taken over at each step: those whose tokens, columns and priority did
  // not change and that parsed without error the time before (moved lines are shifted).
  const std::vector<size_t> reusedCounts = {0, 4, 2, 5, 3, 4, 4, 3, 0};
  Program previous;
  ReusableStatementIndex recorded;
  for (size_t k = 0; k < texts.size(); ++k) {
    INFO("text " << k << ":\n" << texts[k]);
    SourceFile file = SourceFile::make("test.fgsg", texts[k]);
    Diagnostics freshDiags(&file), reusedDiags(&file);
    Program fresh, reused;
    const bool freshOk = parseProgram(file, fresh, freshDiags);
    StatementReuse reuse;
    reuse.offer(previous, std::move(recorded));
    const bool reusedOk = parseProgramReusing(file, reused, reusedDiags, reuse);
    CHECK(reusedOk == freshOk);
    std::ostringstream freshPrinted, reusedPrinted;
    freshDiags.print(freshPrinted);
    reusedDiags.print(reusedPrinted);
    CHECK(programWithPlaces(reused, reusedPrinted.str()) == programWithPlaces(fresh, freshPrinted.str()));
    CHECK(reuse.reusedCount() == reusedCounts[k]);
    recorded = reuse.takeRecorded();
    previous = std::move(reused);
  }
}
