// Collision-tested instancing (FGSG §4.4) in the interpreter: IC culls the rest of its
// production (or, under `collision omit`, drops only itself); a collision deeper in a
// simple placing rule still culls its writer's rest; Lock is all or nothing; IM merges within its thresholds; lines join where they
// meet; and an independent brute-force check finds no two tested instances intersecting.
#include "brute_force_intersection.h"
#include "derive_helpers.h"
#include "runtime/assemble.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

using namespace fgsg;
using namespace fgsg::test;

namespace {

// The symbols whose instances a result holds, in placement order ("B" for each of B's).
std::string placedBy(const rt::DeriveResult& r) {
  std::string s;
  for (const auto& inst : r.instances.instances) s += r.instances.symbols[inst.symbol] + " ";
  return s;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// An obstacle at the origin; B D E each place a sphere far away from everything else.
const std::string kPieces = R"(
Obstacle ~> I("cube")
B ~> T(10, 0, 0) I("sphere")
D ~> T(20, 0, 0) I("sphere")
E ~> T(30, 0, 0) I("sphere")
)";

}  // namespace

TEST_CASE("IC culls the rest of its production on a collision", "[collision]") {
  // FGSG: "A ~> B I("X.obj") D E ... we would further derive shape B, but cull D and E".
  auto hit = deriveText("Axiom ~> Obstacle A\nA ~> B IC(\"cube\") D E\n" + kPieces);
  REQUIRE(hit.ok);
  CHECK(placedBy(hit) == "Obstacle B ");
  CHECK(hit.stats.collisionTests == 1);
  CHECK(hit.stats.collisions == 1);
  auto miss = deriveText("Axiom ~> Obstacle A\nA ~> B T(0, 5, 0) IC(\"cube\") D E\n" + kPieces);
  REQUIRE(miss.ok);
  CHECK(placedBy(miss) == "Obstacle A B D E ");
  CHECK(miss.stats.collisions == 0);
}

TEST_CASE("A collision deeper in a simple placing rule culls its writer's rest", "[collision]") {
  // FGSG: "A ~> B C D E; C ~> F; F ~> I("X.obj")": C is derived depth-first on the spot,
  // its collision counts as C's, and D and E are culled.
  const std::string rules = "A ~> B C D E\nC ~> F\nF ~> IC(\"cube\")\n" + kPieces;
  auto hit = deriveText("Axiom ~> Obstacle A\n" + rules);
  REQUIRE(hit.ok);
  CHECK(placedBy(hit) == "Obstacle B ");
  CHECK(hit.stats.collisions == 1);
  auto miss = deriveText("Axiom ~> Obstacle T(0, 5, 0) A\n" + rules);
  REQUIRE(miss.ok);
  // F is placed as C is written, before B (queued) is derived.
  CHECK(placedBy(miss) == "Obstacle F B D E ");
}

TEST_CASE("A shape that grows further is not derived early", "[collision]") {
  // G recurses, so it waits in the queue as usual; its own collision culls only its own
  // production.
  auto r = deriveText("Axiom ~> Obstacle A\nA ~> G D\nG ~> IC(\"cube\") T(1, 0, 0) G\n" + kPieces,
                      [] { rt::DeriveOptions o; o.maxDepth = 5; return o; }());
  REQUIRE(r.ok);
  CHECK(placedBy(r) == "Obstacle D ");
  CHECK(r.stats.collisions == 1);
}

TEST_CASE("Lock places its set all or nothing", "[collision][lock]") {
  const std::string rules = R"(
L ~> Lock{ P | Q } X
P ~> T(5, 0, 0) IC("sphere")
Q ~> IC("cube")
X ~> T(40, 0, 0) I("disc")
)";
  auto blocked = deriveText("Axiom ~> Obstacle L\n" + rules + kPieces);
  REQUIRE(blocked.ok);
  CHECK(placedBy(blocked) == "Obstacle ");  // P's sphere fitted but went with Q's cube; X culled
  CHECK(blocked.stats.locksRemoved == 1);
  auto free = deriveText("Axiom ~> Obstacle T(0, 7, 0) L\n" + rules + kPieces);
  REQUIRE(free.ok);
  CHECK(placedBy(free) == "Obstacle P Q X ");
  CHECK(free.stats.locksRemoved == 0);
}

TEST_CASE("collision omit drops only what collides and lets the production go on", "[collision][omit]") {
  // FGSG §4.4's other strategy: "A ~> B IC(x) D E": x collides, B, D and E are derived.
  auto hit = deriveText("collision omit;\nAxiom ~> Obstacle A\nA ~> B IC(\"cube\") D E\n" + kPieces);
  REQUIRE(hit.ok);
  CHECK(placedBy(hit) == "Obstacle B D E ");
  CHECK(hit.stats.collisions == 1);
  // Deeper in a simple placing rule: F's cube is dropped, C's writer goes on.
  auto deep = deriveText("collision omit;\nAxiom ~> Obstacle A\nA ~> B C D E\nC ~> F\nF ~> IC(\"cube\")\n" + kPieces);
  REQUIRE(deep.ok);
  CHECK(placedBy(deep) == "Obstacle B D E ");
  // A Lock set still goes whole (P's sphere with Q's cube), and X after it stays.
  const std::string lock = R"(
L ~> Lock{ P | Q } X
P ~> T(5, 0, 0) IC("sphere")
Q ~> IC("cube")
X ~> T(40, 0, 0) I("disc")
)";
  auto set = deriveText("collision omit;\nAxiom ~> Obstacle L\n" + lock + kPieces);
  REQUIRE(set.ok);
  CHECK(placedBy(set) == "Obstacle X ");
  CHECK(set.stats.locksRemoved == 1);
  // The declaration's words: one strategy.
  CHECK_THROWS_WITH(deriveText("collision omit cull;\nAxiom ~> I(\"cube\")\n"),
                    Catch::Contains("E032") && Catch::Contains("two collision strategies, 'omit' and 'cull'"));
}

TEST_CASE("collision distance keeps a clearance between the meshes", "[collision][distance]") {
  // Unit cubes stepped 1.3 apart along X leave gaps of 0.3: a clearance of 0.25 places
  // every one, 0.35 every other (each placed cube is 0.3 from the next, 1.6 from the one
  // after), and the mesh test, which only asks for no contact, places all.
  const std::string row = "Axiom ~> Step(6)\nStep(n) : n > 0 ~> IC(\"cube\") T(1.3, 0, 0) Step(n - 1)\n";
  auto loose = deriveText("collision omit distance 0.25;\n" + row);
  REQUIRE(loose.ok);
  CHECK(loose.instances.instances.size() == 6);
  auto tight = deriveText("collision omit distance 0.35;\n" + row);
  REQUIRE(tight.ok);
  REQUIRE(tight.instances.instances.size() == 3);
  for (size_t i = 0; i < 3; ++i)
    CHECK(unitPoint(tight.instances.instances[i], 0, 0, 0).x() == Approx(2.6 * i).margin(1e-12));
  CHECK(tight.stats.collisions == 3);
  auto contact = deriveText("collision omit;\n" + row);
  CHECK(contact.instances.instances.size() == 6);
  // Culling (the default strategy) stops the row at the first cube too close.
  auto cull = deriveText("collision distance 0.35;\n" + row);
  CHECK(cull.instances.instances.size() == 1);
}

TEST_CASE("IM merges an instance into its twin within the thresholds only", "[collision][merge]") {
  auto near = deriveText("Axiom ~> IM(\"cube\", 0.5, 10) T(0.4, 0, 0) RS(8) IM(\"cube\", 0.5, 10)");
  REQUIRE(near.ok);
  REQUIRE(near.instances.instances.size() == 1);
  CHECK(near.stats.merges == 1);
  // Half way between the two: centres (0.5, 0.5, 0.5) and (0.9, 0.5, 0.5) turned 8 degrees.
  const Eigen::Vector3d c = unitPoint(near.instances.instances[0], 0.5, 0.5, 0.5);
  const double a = 8 * M_PI / 180;
  const Eigen::Vector3d second(0.4 + 0.5 * std::cos(a) - 0.5 * std::sin(a),
                               0.5 * std::sin(a) + 0.5 * std::cos(a), 0.5);
  CHECK((c - 0.5 * (Eigen::Vector3d(0.5, 0.5, 0.5) + second)).norm() < 1e-12);
  auto far = deriveText("Axiom ~> IM(\"cube\", 0.5, 10) T(0.6, 0, 0) IM(\"cube\", 0.5, 10)");
  CHECK(far.instances.instances.size() == 2);
  auto turned = deriveText("Axiom ~> IM(\"cube\", 0.5, 10) RS(12) IM(\"cube\", 0.5, 10)");
  CHECK(turned.instances.instances.size() == 2);
  CHECK(turned.stats.merges == 0);
}

TEST_CASE("Collision-tested patterns have no intersecting instances", "[collision][bruteforce]") {
  std::string grammar = readFile(std::string(FGSG_SOURCE_DIR) + "/examples/fig1_cracks_plane.fgsg");
  REQUIRE(!grammar.empty());
  rt::DeriveOptions opt;
  opt.collideAll = true;
  opt.maxDepth = 14;
  opt.seed = 7;
  auto r = deriveText(grammar, opt);
  REQUIRE(r.ok);
  REQUIRE(r.stats.collisions > 0);  // the cracks do run into each other
  std::vector<size_t> all(r.instances.instances.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  rt::AssetLibrary library;
  library.addSearchDir(std::string(FGSG_SOURCE_DIR) + "/examples/assets");
  CHECK(intersectingPairs(r.instances, all, library).empty());
  // Without the tests (the example declares `collision all;`), the same grammar
  // overlaps: the check can fail.
  std::string untested = grammar;
  const size_t declaration = untested.find("\ncollision all;");
  REQUIRE(declaration != std::string::npos);
  untested.erase(declaration, std::string("\ncollision all;").size());
  opt.collideAll = false;
  opt.maxDepth = 8;
  auto loose = deriveText(untested, opt);
  std::vector<size_t> some(loose.instances.instances.size());
  for (size_t i = 0; i < some.size(); ++i) some[i] = i;
  CHECK_FALSE(intersectingPairs(loose.instances, some, library).empty());
  // Deterministic: the same seed gives the same instances.
  opt.collideAll = true;
  opt.maxDepth = 14;
  auto again = deriveText(grammar, opt);
  REQUIRE(again.instances.instances.size() == r.instances.instances.size());
  for (size_t i = 0; i < r.instances.instances.size(); ++i)
    CHECK(again.instances.instances[i].transform == r.instances.instances[i].transform);
}

TEST_CASE("Collision tests need a sequential derivation", "[collision][errors]") {
  auto r = deriveText("derive parallel 2;\nAxiom ~> A\nA ~> IC(\"cube\") A");
  CHECK_FALSE(r.ok);
  REQUIRE(r.messages.size() == 1);
  CHECK(r.messages[0].code == "R009");
  CHECK(r.messages[0].line == 3);
  CHECK(r.messages[0].col == 6);
}

TEST_CASE("Locked flowers are whole or absent, and never touch", "[collision][lock]") {
  std::string grammar = readFile(std::string(FGSG_SOURCE_DIR) + "/examples/lock_flowers.fgsg");
  REQUIRE(!grammar.empty());
  rt::DeriveOptions opt;
  opt.attrOverrides = {{"flowers", "60"}};
  auto r = deriveText(grammar, opt);
  REQUIRE(r.ok);
  CHECK(r.stats.locksRemoved > 0);
  size_t stems = 0, petals = 0;
  for (const auto& inst : r.instances.instances) {
    const std::string& by = r.instances.symbols[inst.symbol];
    stems += by == "Stem";
    petals += by == "Petal";
  }
  CHECK(stems > 10);
  CHECK(petals == 5 * stems);
  CHECK(stems + petals == r.instances.instances.size());
  CHECK(stems + r.stats.locksRemoved == 60);
  std::vector<size_t> all(r.instances.instances.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  rt::AssetLibrary library;
  CHECK(intersectingPairs(r.instances, all, library).empty());
}

TEST_CASE("A line that reaches another ends exactly on it", "[collision][lines]") {
  auto r = deriveText(R"(
start = [ T(-2, 0, 0) Line(0.1, true) LineSeg(4) ] [ T(0, -1.05, 0) RS(90) Line(0.1, true) V ]
V ~> LineSeg(0.3) V
)");
  REQUIRE(r.ok);
  CHECK(r.stats.linesJoined == 1);
  // The horizontal one, then up to -0.75 -0.45 -0.15 (tubes 0.15 apart: clear of each
  // other) and the join at 0.
  CHECK(r.stats.lineSegments == 5);
  REQUIRE(r.instances.instances.size() == 2);  // one tube per line
  const auto& vertical = r.instances.instances[1];
  CHECK(r.instances.assets[vertical.asset] == "<line 1>");
  // The tube's box runs from its start cap at y = -1.05 to its end cap on the other line's axis.
  CHECK(unitPoint(vertical, 0, 0, 0).y() == Approx(-1.05).margin(1e-9));
  CHECK(unitPoint(vertical, 1, 1, 1).y() == Approx(0).margin(1e-9));
  CHECK(unitPoint(vertical, 0.5, 0.5, 0.5).x() == Approx(0).margin(1e-9));
}

TEST_CASE("LineSeg outside a line is an error at the command", "[collision][lines][errors]") {
  auto r = deriveText("start = T(1, 0, 0) LineSeg(1)");
  CHECK_FALSE(r.ok);
  REQUIRE(r.messages.size() == 1);
  CHECK(r.messages[0].code == "R014");
  CHECK(r.messages[0].col == 20);
}

TEST_CASE("A Lock set that never ends is refused, not a crash", "[collision][lock][errors]") {
  auto r = deriveText("Axiom ~> Lock{ G }\nG ~> T(2, 0, 0) IC(\"cube\") G");
  CHECK_FALSE(r.ok);
  REQUIRE(r.messages.size() == 1);
  CHECK(r.messages[0].code == "R017");
  CHECK(r.messages[0].line == 2);
}

TEST_CASE("a line drawn with an asset bends one instance per segment along the smoothed line", "[lines]") {
  // Three straight steps along X, then three turned 30 degrees: six bark instances, each
  // bent along its segment's curve, every vertex within the bark's radius of the line.
  const auto r = test::deriveText(
      "Axiom ~> Line(0.2, true, \"bark\") A(0);\n"
      "A(n) : n < 3 ~> T(1, 0, 0) LineSeg() A(n + 1);\n"
      "A(n) : n < 6 ~> RZ(10) T(1, 0, 0) LineSeg() A(n + 1);\n");
  REQUIRE(r.ok);
  REQUIRE(r.instances.lines.size() == 1);
  const auto& points = r.instances.lines[0].points;
  REQUIRE(points.size() == 7);
  size_t bark = 0;
  for (const auto& inst : r.instances.instances) {
    if (r.instances.assets[inst.asset] != "bark") continue;
    REQUIRE(inst.curve < r.instances.curves.size());
    CHECK(r.instances.curves[inst.curve].control[0] == points[bark]);
    ++bark;
  }
  CHECK(bark == 6);
  rt::AssetLibrary library;
  std::vector<int> meshOf;
  std::string error;
  REQUIRE(rt::resolveAssets(r.instances, library, meshOf, error));
  const rt::Mesh mesh = rt::assembleInstances(r.instances, library, meshOf);
  REQUIRE(mesh.vertexCount() > 0);
  double farthest = 0;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const Eigen::Vector3d p(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
    double nearest = 1e300;
    for (size_t k = 0; k + 1 < points.size(); ++k) {
      const Eigen::Vector3d a(points[k][0], points[k][1], points[k][2]), b(points[k + 1][0], points[k + 1][1], points[k + 1][2]);
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (p - (a + t * (b - a))).norm());
    }
    farthest = std::max(farthest, nearest);
  }
  // The radius (0.1), and the smooth curve's small departure from the polyline at the turns.
  CHECK(farthest < 0.13);
  CHECK(farthest > 0.09);
}

TEST_CASE("LineSeg with a length moves along the surface, as T does", "[lines][surface]") {
  // On a sphere of radius 2, five LineSeg(0.5) from the start: every point of the line
  // lies on the sphere, consecutive points 0.5 apart along it (a chord of 2 sin(0.125) 2),
  // and a cube placed after them stands where T(2.5, 0, 0) would have taken it.
  const auto r = test::deriveText(
      "surface sphere(2, 6);\nAxiom ~> [ Line(0.05) LineSeg(0.5) LineSeg(0.5) LineSeg(0.5) LineSeg(0.5) "
      "LineSeg(0.5) I(\"cube\") ] T(2.5, 0, 0) I(\"cube\");\n");
  REQUIRE(r.ok);
  REQUIRE(r.instances.lines.size() == 1);
  const auto& points = r.instances.lines[0].points;
  REQUIRE(points.size() == 6);
  for (size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d p(points[k][0], points[k][1], points[k][2]);
    CHECK(p.norm() == Approx(2).epsilon(1e-3));  // the polyhedral sphere's faces sag a little
    if (k > 0) {
      const Eigen::Vector3d q(points[k - 1][0], points[k - 1][1], points[k - 1][2]);
      CHECK((p - q).norm() == Approx(2 * 2 * std::sin(0.5 / 2 / 2)).epsilon(5e-3));
    }
  }
  std::vector<Eigen::Vector3d> cubes;
  for (const auto& inst : r.instances.instances)
    if (r.instances.assets[inst.asset] == "cube") cubes.push_back(unitPoint(inst, 0.5, 0.5, 0.5));
  REQUIRE(cubes.size() == 2);
  CHECK((cubes[0] - cubes[1]).norm() < 1e-9);
}
