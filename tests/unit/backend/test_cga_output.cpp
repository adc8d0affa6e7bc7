// CGA leaves output their own geometry: masses, faces, split pieces and footprint
// polygons come out as exact areas and closed solids of exact volume.
#include "derive_helpers.h"

#include "runtime/assemble.h"

#include <Eigen/Geometry>

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <tuple>

using namespace fgsg;
using Catch::Matchers::Contains;

namespace {

rt::Mesh assembled(const rt::DeriveResult& r) {
  REQUIRE(r.ok);
  rt::AssetLibrary library;
  std::vector<int> meshOf;
  std::string error;
  REQUIRE(rt::resolveAssets(r.instances, library, meshOf, error));
  return rt::assembleInstances(r.instances, library, meshOf);
}

Eigen::Vector3d vertex(const rt::Mesh& m, uint32_t i) {
  return {m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]};
}

// Signed volume by the divergence theorem: positive for a closed, outward-facing mesh.
double volume(const rt::Mesh& m) {
  double v = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    v += vertex(m, m.indices[t]).dot(vertex(m, m.indices[t + 1]).cross(vertex(m, m.indices[t + 2]))) / 6;
  return v;
}

double area(const rt::Mesh& m) {
  double a = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const auto p = vertex(m, m.indices[t]);
    a += 0.5 * (vertex(m, m.indices[t + 1]) - p).cross(vertex(m, m.indices[t + 2]) - p).norm();
  }
  return a;
}

// Closed and consistently oriented: after welding equal positions, every directed edge
// has exactly one partner running the other way.
bool watertight(const rt::Mesh& m) {
  using Key = std::tuple<long, long, long>;
  std::map<Key, uint32_t> weld;
  auto id = [&](uint32_t i) {
    const Eigen::Vector3d p = vertex(m, i) * 1e5;
    return weld.emplace(Key{std::lround(p.x()), std::lround(p.y()), std::lround(p.z())}, uint32_t(weld.size()))
        .first->second;
  };
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) ++edges[{id(m.indices[t + k]), id(m.indices[t + (k + 1) % 3])}];
  for (const auto& [e, n] : edges) {
    auto back = edges.find({e.second, e.first});
    if (n != 1 || back == edges.end() || back->second != 1) return false;
  }
  return !edges.empty();
}

// The output's area per symbol: each instance assembled on its own.
std::map<std::string, double> areaBySymbol(const rt::DeriveResult& r) {
  std::map<std::string, double> areas;
  for (const rt::Instance& inst : r.instances.instances) {
    rt::DeriveResult one = r;
    one.instances.instances = {inst};
    areas[r.instances.symbols[inst.symbol]] += area(assembled(one));
  }
  return areas;
}

}  // namespace

TEST_CASE("A 10 by 6 footprint extruded 3 outputs a closed box of volume 180", "[cga][output]") {
  const rt::Mesh m = assembled(test::deriveText("Lot ~> S(10, 0, 6) Extrude(3) Mass;"));
  CHECK(m.triangleCount() == 12);
  CHECK(volume(m) == Approx(180).epsilon(1e-6));
  CHECK(watertight(m));
}

TEST_CASE("An L-shaped Footprint extruded is a closed prism of its area times the height", "[cga][output]") {
  // Area 10 x 4 + 4 x 6 = 64, given clockwise: the orientation is repaired.
  const rt::Mesh m =
      assembled(test::deriveText("Lot ~> Footprint(0, 0, 0, 10, 4, 10, 4, 4, 10, 4, 10, 0) Extrude(3) Mass;"));
  CHECK(volume(m) == Approx(192).epsilon(1e-6));
  CHECK(watertight(m));
  CHECK(m.boundsMin() == std::array<float, 3>{0, 0, 0});
  CHECK(m.boundsMax() == std::array<float, 3>{10, 3, 10});
}

TEST_CASE("The split pieces of a polygon footprint cover it exactly and face up", "[cga][output]") {
  const rt::DeriveResult r = test::deriveText(
      "Lot ~> Footprint(0, 0, 10, 0, 10, 4, 4, 4, 4, 10, 0, 10) Subdiv(\"X\", 3, 1r){ West | East };");
  REQUIRE(r.instances.instances.size() == 2);
  const rt::Mesh m = assembled(r);
  CHECK(area(m) == Approx(64).epsilon(1e-6));
  for (size_t v = 0; v < m.vertexCount(); ++v) CHECK(m.normals[3 * v + 1] == Approx(1));
  for (size_t v = 0; v < m.vertexCount(); ++v) CHECK(m.positions[3 * v + 1] == 0);
}

TEST_CASE("Comp faces of a mass are leaves with the mass's face areas", "[cga][output]") {
  const rt::DeriveResult r = test::deriveText(
      "Lot ~> S(10, 0, 6) Extrude(3) Comp(\"sidefaces\"){ Wall } Comp(\"top\"){ Top };");
  REQUIRE(r.instances.instances.size() == 5);
  CHECK(area(assembled(r)) == Approx(2 * (10 + 6) * 3 + 60).epsilon(1e-6));
  CHECK(r.instances.symbols[r.instances.instances[0].symbol] == "Wall");
  CHECK(r.instances.symbols[r.instances.instances[4].symbol] == "Top");
}

TEST_CASE("A leaf takes its Color and a flat box leaf is its one upward face", "[cga][output]") {
  const rt::DeriveResult r = test::deriveText("Lot ~> S(4, 0, 5) Color(\"#ff0000\") Plot; Unused ~> Extrude(1) A;");
  const rt::Mesh m = assembled(r);
  CHECK(m.triangleCount() == 2);
  CHECK(area(m) == Approx(20));
  CHECK(m.normals[1] == Approx(1));
  CHECK(m.colors[0] == 1.0f);
  CHECK(m.colors[1] == 0.0f);
}

TEST_CASE("I none places nothing, and outside CGA grammars leaves place nothing", "[cga][output]") {
  CHECK(test::deriveText("Lot ~> S(4, 0, 5) Extrude(2) Mass; Mass ~> I(\"none\");").instances.instances.empty());
  CHECK(test::deriveText("Axiom ~> S(1, 1, 1) Leaf T(2, 0, 0) I(\"cube\");").instances.instances.size() == 1);
}

TEST_CASE("A Footprint that crosses itself or has no area is a located error", "[cga][output]") {
  const rt::DeriveResult bowtie = test::deriveText("Lot ~> Footprint(0, 0, 4, 4, 4, 0, 0, 4) Mass;");
  CHECK_FALSE(bowtie.ok);
  REQUIRE(!bowtie.messages.empty());
  CHECK(bowtie.messages[0].code == "R002");
  CHECK(bowtie.messages[0].line == 1);
  CHECK_THAT(bowtie.messages[0].message, Contains("crosses itself"));
  const rt::DeriveResult flat = test::deriveText("Lot ~> Footprint(0, 0, 4, 0, 8, 0) Mass;");
  CHECK_FALSE(flat.ok);
  CHECK_THAT(flat.messages[0].message, Contains("no area"));
}

TEST_CASE("A hipped roof on an L-shaped Footprint is closed and every slope tilts by the angle", "[cga][output]") {
  // The L's legs are 4 wide: the ridge is 2 tan(30) high; the volume is 176/3 tan(30)
  // (face by face: tests/unit/runtime/test_skeleton_roof.cpp).
  const rt::Mesh m = assembled(test::deriveText(
      "Lot ~> Footprint(0, 0, 10, 0, 10, 4, 4, 4, 4, 10, 0, 10) Roof(\"hipped\", 30){ RoofSolid };"));
  const double t = std::tan(30 * M_PI / 180);
  CHECK(volume(m) == Approx(176.0 / 3 * t).epsilon(1e-6));
  CHECK(watertight(m));
  CHECK(m.boundsMax()[1] == Approx(2 * t).epsilon(1e-6));
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const double ny = m.normals[3 * v + 1];
    if (ny > -0.5) CHECK(std::acos(std::min(1.0, ny)) * 180 / M_PI == Approx(30).epsilon(1e-4));
  }
}

TEST_CASE("A gable roof's ends are triangles: its faces as leaves cover slopes and gables exactly", "[cga][output]") {
  // 10 x 6 at 30 degrees: h = 3 tan(30); slopes 2 x 10 x 3 / cos(30), gables 2 x 6 h / 2.
  const rt::DeriveResult r = test::deriveText(
      "Lot ~> S(10, 0, 6) Roof(\"gable\", 30){ Comp(\"sidefaces\"){ Face } };");
  REQUIRE(r.instances.instances.size() == 4);
  const double h = 3 * std::tan(30 * M_PI / 180);
  CHECK(area(assembled(r)) == Approx(2 * 10 * 3 / std::cos(30 * M_PI / 180) + 6 * h).epsilon(1e-6));
  const rt::Mesh solid = assembled(test::deriveText("Lot ~> S(10, 0, 6) Roof(\"gable\", 30){ Solid };"));
  CHECK(volume(solid) == Approx(10 * 6 * h / 2).epsilon(1e-6));
  CHECK(watertight(solid));
}

TEST_CASE("A roof on an extruded polygon stands on the prism's bottom face", "[cga][output]") {
  const rt::Mesh m = assembled(test::deriveText(
      "Lot ~> Footprint(0, 0, 10, 0, 10, 4, 4, 4, 4, 10, 0, 10) Extrude(5) T(0, 5, 0) Roof(\"shed\", 45){ Shed };"));
  CHECK(watertight(m));
  CHECK(m.boundsMin()[1] == Approx(5));
}

namespace {

rt::Lot lot(std::vector<Eigen::Vector2d> outer, std::vector<std::pair<std::string, double>> numbers,
            std::vector<std::pair<std::string, std::string>> strings = {}) {
  rt::Lot l;
  l.outer = std::move(outer);
  l.numbers = std::move(numbers);
  l.strings = std::move(strings);
  return l;
}

}  // namespace

TEST_CASE("Lots derive the axiom on each footprint with the attrs their properties name", "[cga][lots]") {
  rt::DeriveOptions opt;
  opt.lotsName = "lots.geojson";
  // A 10 x 6 rectangle 5 high and an L (area 64, north up) 2 high; "usage" picks a colour.
  opt.lots.push_back(lot({{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {{"height", 5}, {"unused", 1}}, {{"usage", "shop"}}));
  opt.lots.push_back(lot({{20, 0}, {30, 0}, {30, 4}, {24, 4}, {24, 10}, {20, 10}}, {{"height", 2}}));
  const rt::DeriveResult r = test::deriveText(
      "attr height = 1; attr usage = \"home\"; attr lot_area = 0;\n"
      "Lot : usage == \"shop\" ~> Color(1, 0, 0) Extrude(height) Mass;\n"
      "Lot ~> Color(0, 0, lot_area / 100) Extrude(height) Mass;",
      opt);
  REQUIRE(r.instances.instances.size() == 2);
  const rt::Mesh m = assembled(r);
  CHECK(volume(m) == Approx(60 * 5 + 64 * 2).epsilon(1e-6));
  CHECK(watertight(m));
  CHECK(r.instances.instances[0].color == std::array<float, 3>{1, 0, 0});
  CHECK(r.instances.instances[1].color[2] == Approx(0.64f));
  // North (+y) is -Z: the L's second lot lies at z from -10 to 0.
  CHECK(m.boundsMin()[2] == Approx(-10));
  CHECK(m.boundsMax()[2] == Approx(0));
}

TEST_CASE("Lot.area and Lot.prop read a lot without declaring attrs, defaults without lots", "[cga][lots]") {
  const std::string grammar =
      "Lot : Lot.prop(\"usage\", \"home\") == \"shop\" ~> Color(1, 0, 0) Extrude(Lot.prop(\"height\", 1)) Mass;\n"
      "Lot ~> Color(0, 0, Lot.area / 100) Extrude(Lot.prop(\"height\", 1)) Mass;";
  rt::DeriveOptions opt;
  opt.lotsName = "lots.geojson";
  opt.lots.push_back(lot({{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {{"height", 5}}, {{"usage", "shop"}}));
  opt.lots.push_back(lot({{20, 0}, {30, 0}, {30, 4}, {24, 4}, {24, 10}, {20, 10}}, {{"height", 2}}));
  const rt::DeriveResult r = test::deriveText(grammar, opt);
  REQUIRE(r.instances.instances.size() == 2);
  CHECK(volume(assembled(r)) == Approx(60 * 5 + 64 * 2).epsilon(1e-6));
  CHECK(r.instances.instances[0].color == std::array<float, 3>{1, 0, 0});
  CHECK(r.instances.instances[1].color[2] == Approx(0.64f));
  // CGA's Lot.props.height reads the same property (0 without it).
  const rt::DeriveResult props = test::deriveText("Lot ~> Extrude(Lot.props.height) Mass;", opt);
  CHECK(volume(assembled(props)) == Approx(60 * 5 + 64 * 2).epsilon(1e-6));
  // Without lots: the defaults (a 1 m high box on the axiom's flat scope, area 0).
  const rt::DeriveResult plain = test::deriveText(
      "Lot ~> Footprint(0, 0, 4, 0, 4, 3, 0, 3) Color(0, 1, Lot.area) Extrude(Lot.prop(\"height\", 1)) Mass;");
  REQUIRE(plain.ok);
  CHECK(volume(assembled(plain)) == Approx(12).epsilon(1e-6));
  CHECK(plain.instances.instances[0].color[2] == 0.0f);
}

TEST_CASE("A lot property that does not fit its attr is an error naming the lot", "[cga][lots]") {
  rt::DeriveOptions opt;
  opt.lotsName = "lots.geojson";
  opt.lots.push_back(lot({{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}, {{"height", "tall"}}));
  opt.lots.back().id = "A-7";
  const rt::DeriveResult r = test::deriveText("attr height = 1; Lot ~> Extrude(height) Mass;", opt);
  CHECK_FALSE(r.ok);
  REQUIRE(!r.messages.empty());
  CHECK(r.messages[0].code == "R010");
  CHECK(r.messages[0].message == "lots.geojson: feature 0 (id \"A-7\"): property height=tall: expected a number");
}

TEST_CASE("Each lot has a random stream of its own", "[cga][lots]") {
  rt::DeriveOptions opt;
  for (int k = 0; k < 2; ++k) opt.lots.push_back(lot({{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}));
  const char* grammar = "Lot ~> Extrude(Rand(1, 100)) Mass;";
  const rt::DeriveResult a = test::deriveText(grammar, opt), b = test::deriveText(grammar, opt);
  REQUIRE(a.instances.instances.size() == 2);
  CHECK(a.instances.instances[0].transform[5] != a.instances.instances[1].transform[5]);
  CHECK(a.instances.instances[1].transform == b.instances.instances[1].transform);
}

TEST_CASE("A courtyard lot is built with its hole: walls inside and out, a roof around it", "[cga][lots]") {
  rt::DeriveOptions opt;
  opt.lots.push_back(lot({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}));
  opt.lots.back().holes.push_back({{3, 3}, {3, 7}, {7, 7}, {7, 3}});
  const rt::Mesh mass = assembled(test::deriveText("Lot ~> Extrude(3) Mass;", opt));
  CHECK(volume(mass) == Approx((100 - 16) * 3).epsilon(1e-6));
  CHECK(watertight(mass));
  const rt::DeriveResult walls = test::deriveText("Lot ~> Extrude(3) Comp(\"sidefaces\"){ Wall };", opt);
  CHECK(walls.instances.instances.size() == 8);
  CHECK(area(assembled(walls)) == Approx((40 + 16) * 3).epsilon(1e-6));
  // Hipped around the courtyard: the ring is 3 wide, so the ridge is 1.5 tan(30) high
  // and the volume 63 tan(30) (tests/unit/runtime/test_skeleton_roof.cpp).
  const double t = std::tan(30 * M_PI / 180);
  const rt::Mesh roof =
      assembled(test::deriveText("Lot ~> Extrude(3) Comp(\"top\"){ Roof(\"hipped\", 30){ RoofSolid } };", opt));
  CHECK(volume(roof) == Approx(63 * t).epsilon(1e-6));
  CHECK(watertight(roof));
  CHECK(roof.boundsMax()[1] == Approx(3 + 1.5 * t).epsilon(1e-6));
}

TEST_CASE("A lot whose hole crosses its outline is an error naming the lot", "[cga][lots]") {
  rt::DeriveOptions opt;
  opt.lotsName = "lots.geojson";
  opt.lots.push_back(lot({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}));
  opt.lots.back().holes.push_back({{8, 3}, {8, 7}, {12, 7}, {12, 3}});
  const rt::DeriveResult r = test::deriveText("Lot ~> Extrude(3) Mass;", opt);
  CHECK_FALSE(r.ok);
  REQUIRE(!r.messages.empty());
  CHECK(r.messages[0].code == "R028");
  CHECK_THAT(r.messages[0].message, Contains("lots.geojson: feature 0: Footprint: hole 0 is not strictly inside"));
}

TEST_CASE("Comp with labelled parts sends each face to the first part that names it", "[cga][output]") {
  // 10 x 3 x 6: front 30, back 30, left and right 18 each, top 60 (bottom: no part).
  const rt::DeriveResult r = test::deriveText(
      "Lot ~> S(10, 3, 6) Comp(\"f\"){ front: Front | top: Top | side: Side | all: Rest };");
  std::map<std::string, int> countOf;
  for (const auto& inst : r.instances.instances) ++countOf[r.instances.symbols[inst.symbol]];
  CHECK(countOf["Front"] == 1);
  CHECK(countOf["Top"] == 1);
  CHECK(countOf["Side"] == 3);  // back, left, right: front went to the first part
  CHECK(countOf["Rest"] == 1);  // the bottom
  CHECK(area(assembled(r)) == Approx(2 * (30 + 18 + 60)).epsilon(1e-6));
}

TEST_CASE("Offset sets a lot's inside back from every edge and leaves the border band", "[cga][output]") {
  // 10 x 6 set back by 1: inside 8 x 4, border 60 - 32.
  const rt::DeriveResult r =
      test::deriveText("Lot ~> S(10, 0, 6) Offset(1){ inside: Inside | border: Border };");
  const std::map<std::string, double> areaOf = areaBySymbol(r);
  CHECK(areaOf.at("Inside") == Approx(32).epsilon(1e-6));
  CHECK(areaOf.at("Border") == Approx(28).epsilon(1e-6));
  // An L with legs 4 wide set back by 1.5 keeps a 1-wide L: (10 - 3) x 1 + (10 - 4) x 1... by area.
  const rt::Mesh l = assembled(test::deriveText(
      "Lot ~> Footprint(0, 0, 10, 0, 10, 4, 4, 4, 4, 10, 0, 10) Offset(1.5){ inside: Building };"));
  CHECK(area(l) == Approx(7 * 1 + 6 * 1).epsilon(1e-6));
  // Set back further than the lot is deep: no inside at all.
  CHECK(test::deriveText("Lot ~> S(10, 0, 6) Offset(4){ inside: A };").instances.instances.empty());
}

TEST_CASE("The inside of an Offset is a footprint: it extrudes to a closed building", "[cga][output]") {
  const rt::Mesh m = assembled(test::deriveText("Lot ~> S(10, 0, 6) Offset(1){ inside: Extrude(5) Mass };"));
  CHECK(volume(m) == Approx(8 * 4 * 5).epsilon(1e-6));
  CHECK(watertight(m));
  CHECK(m.boundsMin()[0] == Approx(1));
  CHECK(m.boundsMin()[2] == Approx(1));
}

TEST_CASE("Offset on a courtyard lot: inside and border bands add up to the lot", "[cga][lots]") {
  rt::DeriveOptions opt;
  opt.lots.push_back(lot({{0, 0}, {20, 0}, {20, 20}, {0, 20}}, {}));
  opt.lots.back().holes.push_back({{8, 8}, {8, 12}, {12, 12}, {12, 8}});
  // Set back by 2: the inside is 16 x 16 minus the 8 x 8 grown court, 192; the border
  // is the outer band 400 - 256 and the court's band 64 - 16.
  const rt::DeriveResult r = test::deriveText("Lot ~> Offset(2){ inside: Inside | border: Border };", opt);
  const std::map<std::string, double> areaOf = areaBySymbol(r);
  CHECK(areaOf.at("Inside") == Approx(256 - 64).epsilon(1e-6));
  CHECK(areaOf.at("Border") == Approx(144 + 48).epsilon(1e-6));
}

TEST_CASE("Comp takes a roof's eaves, ridges, rakes, hips and valleys", "[cga][output]") {
  // Each selected edge places one cube (an edge outputs no geometry of its own).
  auto count = [](const std::string& roof, const std::string& selector) {
    const auto r = test::deriveText(roof + "{ Comp(\"" + selector + "\"){ E } };\nE ~> I(\"cube\");");
    REQUIRE(r.ok);
    return r.instances.instances.size();
  };
  const std::string hipped = "A ~> S(10, 3, 6) Roof(\"hipped\", 35)", gable = "A ~> S(10, 3, 6) Roof(\"gable\", 35)";
  const std::string ell = "A ~> Footprint(0, 0, 20, 0, 20, 9, 9, 9, 9, 18, 0, 18) Roof(\"hipped\", 30)";
  CHECK(count(hipped, "eaves") == 4);
  CHECK(count(hipped, "ridges") == 1);
  CHECK(count(hipped, "hips") == 4);
  CHECK(count(hipped, "rakes") == 0);
  CHECK(count(hipped, "valleys") == 0);
  CHECK(count(gable, "rakes") == 4);  // the gable ends' sloped edges
  CHECK(count(gable, "hips") == 0);
  CHECK(count(gable, "ridges") == 1);
  // An L: the concave corner's valley, five hips, two ridges, six eaves.
  CHECK(count(ell, "valleys") == 1);
  CHECK(count(ell, "hips") == 5);
  CHECK(count(ell, "ridges") == 2);
  CHECK(count(ell, "eaves") == 6);
  // A shed: one slope, its low edge the eave, its high edge (against the upright back
  // wall) the mono-pitch ridge, the side triangles' sloped edges the two rakes; the back
  // wall's upright corners are of no class.
  const std::string shed = "A ~> S(10, 3, 6) Roof(\"shed\", 20)";
  CHECK(count(shed, "eaves") == 1);
  CHECK(count(shed, "ridges") == 1);
  CHECK(count(shed, "rakes") == 2);
  CHECK(count(shed, "hips") == 0);
  CHECK(count(shed, "valleys") == 0);
}

TEST_CASE("A flat roof with a parapet is an Offset band extruded: a closed ring of the band's area", "[cga][output]") {
  // L footprint: area 261, perimeter 76, five convex corners and one concave; the band
  // 0.4 wide has area P d - (5 - 1) d^2 = 29.76, so the parapet 1.1 high holds 32.736.
  const rt::Mesh parapet = assembled(test::deriveText(
      "Lot ~> Footprint(0, 0, 20, 0, 20, 9, 9, 9, 9, 18, 0, 18) Offset(0.4){ inside: ε | border: Extrude(1.1) Parapet };"));
  CHECK(volume(parapet) == Approx(32.736).epsilon(1e-5));  // float vertices
  CHECK(watertight(parapet));
}

TEST_CASE("A Footprint with a hole is a courtyard: walls around both rings, a roof around the court", "[cga][output]") {
  const std::string lot = "Lot ~> Footprint(0, 0, 30, 0, 30, 20, 0, 20, \"hole\", 10, 5, 20, 5, 20, 15, 10, 15)";
  const rt::Mesh mass = assembled(test::deriveText(lot + " Extrude(3) Mass;"));
  CHECK(volume(mass) == Approx((600.0 - 100.0) * 3).epsilon(1e-6));
  CHECK(watertight(mass));
  const rt::Mesh roof = assembled(test::deriveText(lot + " Roof(\"hipped\", 30){ RoofSolid };"));
  // Corners as pairs are the same footprint.
  const rt::Mesh paired = assembled(test::deriveText(
      "Lot ~> Footprint((0, 0), (30, 0), (30, 20), (0, 20), \"hole\", (10, 5), (20, 5), (20, 15), (10, 15)) "
      "Extrude(3) Mass;"));
  CHECK(volume(paired) == Approx(volume(mass)));
  CHECK(watertight(roof));
  CHECK(volume(roof) > 0);
  // A hole that leaves the outline is a located error naming it.
  const auto outside = test::deriveText(
      "Lot ~> Footprint(0, 0, 30, 0, 30, 20, 0, 20, \"hole\", 25, 5, 35, 5, 35, 15, 25, 15) Mass;");
  REQUIRE_FALSE(outside.ok);
  CHECK(outside.messages[0].code == "R002");
  CHECK_THAT(outside.messages[0].message, Contains("hole 0"));
}
