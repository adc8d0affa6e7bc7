// Semantic analysis of `surface` and `field` declarations (frontend/sema_environment.cpp):
// every accepted form evaluated to constants, and every error (E033..E040) at its place.
#include "sema_helpers.h"

#include <catch2/catch.hpp>

#include <sstream>

using namespace fgsg::frontend;
using namespace fgsg::frontend::test;

namespace {

using Words = std::vector<std::pair<std::string, std::vector<double>>>;

}  // namespace

// ------------------------------------------------------------------ surfaces

TEST_CASE("surface: a mesh file or a procedural surface with constant arguments",
          "[sema][environment]") {
  auto file = declarations("surface \"bunny.off\";");
  REQUIRE(file.ok);
  CHECK(file.sema.surface.present);
  CHECK(file.sema.surface.path == "bunny.off");
  CHECK(file.sema.surface.generator.empty());

  auto torus = declarations("const R = 2;\nsurface torus(R, R * 0.3);");
  INFO(torus.printed);
  REQUIRE(torus.ok);
  CHECK(torus.sema.surface.generator == "torus");
  REQUIRE(torus.sema.surface.args.size() == 2);
  CHECK(torus.sema.surface.args[0] == 2);
  CHECK(torus.sema.surface.args[1] == Approx(0.6));
  CHECK(torus.sema.surface.range.begin.line == 2);

  struct Case {
    const char* text;
    const char* generator;
    std::vector<double> args;
  };
  for (const Case& c : {Case{"surface sphere(1.5);", "sphere", {1.5}},
                        Case{"surface plane(10, 20);", "plane", {10, 20}},
                        Case{"surface genus2();", "genus2", {}},
                        Case{"surface genus2;", "genus2", {}},
                        Case{"surface cylinder(sqrt(4), 3);", "cylinder", {2, 3}}}) {
    auto a = declarations(c.text);
    INFO(c.text << "\n" << a.printed);
    REQUIRE(a.ok);
    CHECK(a.sema.surface.present);
    CHECK(a.sema.surface.generator == c.generator);
    CHECK(a.sema.surface.args == c.args);
  }

  auto none = declarations("");
  CHECK_FALSE(none.sema.surface.present);
}

TEST_CASE("surface errors: generator, argument count, empty file name (E033)", "[sema][environment]") {
  onlyError(declarations("surface bunny;"), "E033", 1, 9,
            "unknown surface 'bunny' (expected torus(R, r), sphere(r), plane(w, h), genus2(), "
            "cylinder(r, h) or tori3(R, r); a mesh file is written as a string: `surface \"bunny.off\";`)");
  onlyError(declarations("surface tori3(2, 1);"), "E034", 1, 18,
            "the tube radius r = 1 of tori3(R, r) must be less than half the radius R = 2");
  onlyError(declarations("surface torus(2);"), "E033", 1, 9,
            "'torus' takes 2 arguments and an optional resolution, got 1: torus(R, r)");
  onlyError(declarations("surface sphere;"), "E033", 1, 9,
            "'sphere' takes 1 argument and an optional resolution, got 0: sphere(r)");
  onlyError(declarations("surface genus2(1, 2);"), "E033", 1, 9,
            "'genus2' takes 0 arguments and an optional resolution, got 2");
  // The optional resolution after the arguments is accepted.
  CHECK(declarations("surface plane(16, 16, 128);").ok);
  onlyError(declarations("surface plane(16, 16, 0);"), "E034", 1, 23,
            "'resolution' of plane(w, h) must be a positive number, got 0");
  onlyError(declarations("surface \"\";"), "E033", 1, 9, "the surface's file name is empty");
}

TEST_CASE("surface errors: arguments are positive constant numbers (E034)", "[sema][environment]") {
  onlyError(declarations("attr big = 3;\nsurface torus(big, 1);"), "E034", 2, 15,
            "'R' of torus(R, r) must be a constant number");
  onlyError(declarations("surface sphere(\"big\");"), "E034", 1, 16,
            "'r' of sphere(r) must be a number, got a string");
  onlyError(declarations("surface plane(10, -1);"), "E034", 1, 19,
            "'h' of plane(w, h) must be a positive number, got -1");
  onlyError(declarations("surface cylinder(0, 1);"), "E034", 1, 18,
            "'r' of cylinder(r, h) must be a positive number, got 0");
  onlyError(declarations("surface torus(1, 2);"), "E034", 1, 18,
            "the tube radius r = 2 of torus(R, r) must be smaller than the radius R = 1");
  // An unknown name is E010's business elsewhere; here it is simply not constant.
  onlyError(declarations("surface sphere(radius);"), "E034", 1, 16, "must be a constant number");
}

TEST_CASE("surface: only one (E029)", "[sema][environment]") {
  auto a = declarations("surface sphere(1);\nsurface \"b.off\";");
  onlyError(a, "E029", 2, 1, "only one surface may be declared");
  CHECK(a.sema.surface.generator == "sphere");
}

// ------------------------------------------------------------------ fields

TEST_CASE("fields: files, designs and curvature, in declaration order", "[sema][environment]") {
  auto a = declarations(R"(surface torus(2, 0.6);
const foot = "foot.tfield";
const d = 2;
const n = 120;
const p = (0, 0, 1);
field F1 = tensor("a.tfield");
field F2 = design tensor { center at vertex n; wedge at (0.2,0.1,0.9) decay d; smooth 300; };
field K = curvature;
field V = vector("flow.vfield");
field F3 = tensor(foot);
field W = design vector {
  regular at p direction (1, 0, 0) strength -1;
  regular at vertex 3 angle pi decay (d * 2);
  node at vertex 0; centre at vertex 1; saddle at (1, 2, 3) strength 0.5;
  smooth iterations 10;
};
field T = design tensor { trisector at vertex 7 decay 1e-1; node at p; regular at vertex 2 angle -30; };
)");
  INFO(a.printed);
  REQUIRE(a.ok);
  CHECK(a.sema.fields == std::vector<std::string>{"F1", "F2", "K", "V", "F3", "W", "T"});
  const auto& f = a.sema.fieldSpecs;
  REQUIRE(f.size() == 7);

  CHECK(f[0].name == "F1");
  CHECK(f[0].source == "file");
  CHECK(f[0].kind == "tensor");
  CHECK(f[0].path == "a.tfield");
  CHECK(f[0].range.begin.line == 6);

  CHECK(f[1].source == "design");
  CHECK(f[1].kind == "tensor");
  CHECK(f[1].path.empty());
  REQUIRE(f[1].design.size() == 3);
  CHECK(f[1].design[0].kind == "centre");  // `center` is normalised
  CHECK(f[1].design[0].words == Words{{"vertex", {120}}});
  CHECK(f[1].design[0].range.begin.line == 7);
  CHECK(f[1].design[0].range.begin.col == 28);
  CHECK(f[1].design[1].kind == "wedge");
  CHECK(f[1].design[1].words == Words{{"at", {0.2, 0.1, 0.9}}, {"decay", {2}}});
  CHECK(f[1].design[2].kind == "smooth");
  CHECK(f[1].design[2].words == Words{{"iterations", {300}}});

  CHECK(f[2].name == "K");
  CHECK(f[2].source == "curvature");
  CHECK(f[2].kind == "tensor");

  CHECK(f[3].source == "file");
  CHECK(f[3].kind == "vector");
  CHECK(f[3].path == "flow.vfield");

  CHECK(f[4].source == "file");  // a const string path
  CHECK(f[4].path == "foot.tfield");

  CHECK(f[5].kind == "vector");
  REQUIRE(f[5].design.size() == 6);
  CHECK(f[5].design[0].kind == "regular");
  CHECK(f[5].design[0].words ==
        Words{{"at", {0, 0, 1}}, {"direction", {1, 0, 0}}, {"strength", {-1}}});
  CHECK(f[5].design[1].words[0] == std::pair<std::string, std::vector<double>>{"vertex", {3}});
  CHECK(f[5].design[1].words[1].first == "angle");
  CHECK(f[5].design[1].words[1].second[0] == Approx(3.14159265358979));
  CHECK(f[5].design[1].words[2] == std::pair<std::string, std::vector<double>>{"decay", {4}});
  CHECK(f[5].design[2].kind == "node");
  CHECK(f[5].design[3].kind == "centre");
  CHECK(f[5].design[4].kind == "saddle");
  CHECK(f[5].design[4].words == Words{{"at", {1, 2, 3}}, {"strength", {0.5}}});
  CHECK(f[5].design[5].words == Words{{"iterations", {10}}});

  REQUIRE(f[6].design.size() == 3);
  CHECK(f[6].design[0].words == Words{{"vertex", {7}}, {"decay", {0.1}}});
  CHECK(f[6].design[1].words == Words{{"at", {0, 0, 1}}});
  CHECK(f[6].design[2].words == Words{{"vertex", {2}}, {"angle", {-30}}});
}

TEST_CASE("fields: queries name declared fields", "[sema][environment]") {
  auto a = analyse("surface plane(10, 10);\nfield V = vector(\"v.vfield\");\nA : V.length > 1 ~> T(V.value, 0, 0) I(\"cube\");");
  INFO(a.printed);
  CHECK(a.ok);
  auto unknown = analyse("surface plane(10, 10);\nfield V = vector(\"v.vfield\");\nA : W.length > 1 ~> I(\"cube\");");
  onlyError(unknown, "E025", 3, 5, "'W' is not a field");
}

TEST_CASE("fields need a surface (E037)", "[sema][environment]") {
  auto a = declarations("field F1 = curvature;\nfield F2 = tensor(\"f.tfield\");");
  onlyError(a, "E037", 1, 7, "field 'F1' needs a surface: fields live on surfaces");
  auto onPlane = declarations("surface plane(8, 8);\nfield F1 = design tensor { wedge at (1, 1, 0); };");
  CHECK(onPlane.ok);
}

TEST_CASE("field names: unique, not Scope, Shape or context (E022, E036)", "[sema][environment]") {
  onlyError(declarations("surface sphere(1);\nfield F = curvature;\nfield F = curvature;"), "E022", 3, 1,
            "field 'F' is declared twice");
  onlyError(declarations("surface sphere(1);\ntexture F = \"p.png\";\nfield F = curvature;"), "E022", 2, 1,
            "texture 'F' is declared twice");
  onlyError(declarations("surface sphere(1);\nfield Scope = curvature;"), "E036", 2, 7,
            "a field cannot be called 'Scope'");
  onlyError(declarations("surface sphere(1);\nfield Shape = curvature;"), "E036", 2, 7);
  onlyError(declarations("surface sphere(1);\nfield context = curvature;"), "E036", 2, 7);
}

TEST_CASE("a scalar field's expression over the surface: x, y, z, consts, attrs and math", "[sema][environment]") {
  const std::string s = "surface sphere(1);\nconst a = 2;\nattr b = 0.5;\n";
  auto ok = declarations(s + "field F = scalar(a * x + b * sin(30 * y) + z ^ 2);");
  INFO(ok.printed);
  REQUIRE(ok.ok);
  REQUIRE(ok.sema.fieldSpecs.size() == 1);
  CHECK(ok.sema.fieldSpecs[0].source == "expression");
  CHECK(ok.sema.fieldSpecs[0].kind == "scalar");
  CHECK(ok.sema.fieldSpecs[0].expression != nullptr);
  CHECK(declarations(s + "field F = scalar(3);").ok);  // a constant field
  onlyError(declarations(s + "field F = scalar(x + w);"), "E010", 4, 22,
            "unknown name 'w' (not x, y, z, a const or an attr)");
  onlyError(declarations(s + "field F = scalar(x > 1);"), "E013", 4, 18,
            "a scalar field's expression must be a number, but this is a boolean");
  onlyError(declarations(s + "field F = scalar(1 + Scope.sx);"), "E035", 4, 22,
            "it may use x, y, z, numbers, consts, attrs and math functions, not the query 'Scope.sx'");
}

TEST_CASE("field sources (E035)", "[sema][environment]") {
  const std::string s = "surface sphere(1);\n";
  onlyError(declarations(s + "field F = blend(A, B);"), "E035", 2, 11,
            "unknown field source 'blend' (expected tensor(\"file\"), vector(\"file\"), scalar(\"file\"), "
            "design tensor { ... }, design vector { ... }, curvature or image(\"file\"))");
  onlyError(declarations(s + "field F = image(3);"), "E035", 2, 17, "'image' reads a picture");
  onlyError(declarations(s + "field F = scalar();"), "E035", 2, 11, "'scalar' takes one argument");
  onlyError(declarations(s + "field F = scalar(1, 2);"), "E035", 2, 11, "'scalar' takes one argument");
  onlyError(declarations(s + "field F = design scalar { wedge at vertex 0; };"), "E035", 2, 18,
            "a design makes a tensor or a vector field");
  onlyError(declarations(s + "field F = tensor(1);"), "E035", 2, 18,
            "'tensor' loads a field from a file and takes its path as a constant string");
  onlyError(declarations(s + "field F = vector;"), "E035", 2, 11, "'vector' loads a field from a file");
  onlyError(declarations(s + "field F = tensor(\"a\", \"b\");"), "E035", 2, 11);
  onlyError(declarations(s + "field F = tensor(\"\");"), "E035", 2, 11, "the field's file name is empty");
  onlyError(declarations(s + "field F = curvature(1);"), "E035", 2, 11, "'curvature' takes no arguments");
  onlyError(declarations(s + "field F = design;"), "E035", 2, 11, "a design names the field's kind");
  onlyError(declarations(s + "field F = design matrix { wedge at vertex 0; };"), "E035", 2, 18,
            "a design makes a tensor or a vector field");
}

// ------------------------------------------------------------------ designs

namespace {
Analysed design(const std::string& items, const std::string& kind = "tensor") {
  return declarations("surface sphere(1);\nconst d = 2;\nattr a = 1;\nfield F = design " + kind +
                      " { " + items + " };");
}
// Column of the design items on line 4: after "field F = design tensor { ".
constexpr int kItems = 27;
}  // namespace

TEST_CASE("design elements (E038)", "[sema][environment]") {
  onlyError(design("focus at vertex 1;"), "E038", 4, kItems,
            "unknown design element 'focus' (expected regular, wedge, trisector, node, centre (or "
            "center), saddle, or smooth N)");
  onlyError(design("node at vertex 1; wedge at vertex 2;", "vector"), "E038", 4, kItems + 18,
            "a vector field has no wedges");
  onlyError(design("trisector at vertex 2;", "vector"), "E038", 4, kItems, "no trisectors");
  onlyError(design(""), "E038", 4, 11, "a design needs at least one element");
  onlyError(design("smooth 10;"), "E038", 4, 11, "a design needs at least one element");
  onlyError(design("wedge at vertex 0; smooth 10; smooth 20;"), "E038", 4, kItems + 30,
            "'smooth' is written twice in this design (first on line 4)");
}

TEST_CASE("design keywords (E039)", "[sema][environment]") {
  onlyError(design("wedge at vertex 1 decai 2;"), "E039", 4, kItems + 18,
            "unknown word 'decai' in a wedge element (expected at vertex N, at (x, y, z), decay d, "
            "strength s)");
  onlyError(design("regular at vertex 1 iterations 2;"), "E039", 4, kItems + 20,
            "unknown word 'iterations' in a regular element (expected at vertex N, at (x, y, z), "
            "decay d, strength s, direction (x, y, z), angle a)");
  onlyError(design("wedge at vertex 1 direction (1, 0, 0);"), "E039", 4, kItems + 18,
            "'direction' is for regular elements only");
  onlyError(design("saddle at vertex 1 angle 30;"), "E039", 4, kItems + 19,
            "'angle' is for regular elements only");
  onlyError(design("wedge decay 2;"), "E039", 4, kItems,
            "a wedge needs a position: `wedge at vertex 0;` or `wedge at (x, y, z);`");
  onlyError(design("center at vertex 1 at (0, 0, 1);"), "E039", 4, kItems + 19,
            "this centre has two positions");
  onlyError(design("wedge at vertex 1 decay 1 decay 2;"), "E039", 4, kItems + 26,
            "'decay' is written twice in this wedge");
  onlyError(design("regular at vertex 0 direction (1, 0, 0) angle 30;"), "E039", 4, kItems + 40,
            "a regular element takes a direction or an angle, not both");
  onlyError(design("smooth 3 times;"), "E039", 4, 36, "'smooth' takes only its number of iterations");
  onlyError(design("wedge at vertex 0; smooth 3 4;"), "E039", 4, kItems + 28,
            "'smooth' takes one number of iterations");

  auto bare = design("wedge (1, 2, 3);");
  CHECK(has(bare, "E039", 4, kItems + 6));  // a value without its keyword
  CHECK(has(bare, "E039", 4, kItems));      // and so no position
  auto vertex = design("wedge vertex 3;");
  CHECK(has(vertex, "E039", 4, kItems + 6));  // `at vertex N`
}

TEST_CASE("design values (E040)", "[sema][environment]") {
  onlyError(design("wedge at vertex 1 decay;"), "E040", 4, kItems + 18, "'decay' needs a value: `decay 2`");
  onlyError(design("wedge at;"), "E040", 4, kItems + 6, "'at' needs a value");
  onlyError(design("wedge at vertex;"), "E040", 4, kItems + 6, "'at vertex' needs a value: `at vertex 120`");
  onlyError(design("wedge at vertex 0; smooth;"), "E040", 4, kItems + 19,
            "'smooth' needs its number of iterations");
  onlyError(design("wedge at 5;"), "E040", 4, kItems + 9, "'at' takes a point (x, y, z), got a number");
  onlyError(design("wedge at vertex (1, 2, 3);"), "E040", 4, kItems + 16,
            "'at vertex' takes a number, got a vector");
  onlyError(design("regular at vertex 0 direction 2;"), "E040", 4, kItems + 30,
            "'direction' takes a point (x, y, z), got a number");
  onlyError(design("wedge at vertex 0 decay (1, 2, 3);"), "E040", 4, kItems + 24,
            "'decay' takes a number, got a vector");
  onlyError(design("wedge at vertex 0 strength \"big\";"), "E040", 4, kItems + 27,
            "'strength' takes a number, got a string");
  onlyError(design("wedge at (1, 2);"), "E040", 4, kItems + 9, "'at' takes a point of three coordinates");
  onlyError(design("wedge at vertex 0 decay (a);"), "E040", 4, kItems + 24,
            "the value of 'decay' must be a constant");
  onlyError(design("wedge at vertex 0 decay a;"), "E040", 4, kItems + 24,
            "the value of 'decay' must be a constant, and 'a' is an attr");
  onlyError(design("wedge at vertex 1.5;"), "E040", 4, kItems + 16,
            "a vertex number is a whole number from 0 to 2147483647, got 1.5");
  onlyError(design("wedge at vertex -1;"), "E040", 4, kItems + 16, "got -1");
  onlyError(design("wedge at vertex 0 decay 0;"), "E040", 4, kItems + 24, "'decay' must be positive, got 0");
  onlyError(design("wedge at vertex 0 decay (-d);"), "E040", 4, kItems + 24, "got -2");
  onlyError(design("regular at vertex 0 direction (0, 0, 0);"), "E040", 4, kItems + 30,
            "a direction must not be (0, 0, 0)");
  onlyError(design("wedge at vertex 0; smooth 2.5;"), "E040", 4, kItems + 26,
            "the number of smoothing iterations is a whole number from 0 to 2147483647, got 2.5");
}

TEST_CASE("design values may name constants", "[sema][environment]") {
  auto a = declarations(R"(surface sphere(1);
const v = 12;
const d = 0.5;
const p = (1, 0, 0);
const k = 40;
field F = design tensor { wedge at vertex v decay d; regular at p angle d strength d; smooth k; };
)");
  INFO(a.printed);
  REQUIRE(a.ok);
  const auto& items = a.sema.fieldSpecs.at(0).design;
  REQUIRE(items.size() == 3);
  CHECK(items[0].words == Words{{"vertex", {12}}, {"decay", {0.5}}});
  CHECK(items[1].words == Words{{"at", {1, 0, 0}}, {"angle", {0.5}}, {"strength", {0.5}}});
  CHECK(items[2].words == Words{{"iterations", {40}}});

  // A name that is no constant stays an (unknown) keyword.
  auto notConstant = design("wedge at vertex 0 decay e;");
  CHECK(has(notConstant, "E040", 4, kItems + 18));  // 'decay' needs a value
  CHECK(has(notConstant, "E039", 4, kItems + 24));  // unknown word 'e'
  CHECK(notConstant.diags.size() == 2);
}
