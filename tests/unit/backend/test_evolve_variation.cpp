// Chan & Hui §6.4 in a grammar (backend/commands/evolve_command.cpp): a tileset's
// `faces "+z";` puts its own evolved pattern on the face-lets facing those ways, and
// `colours L;` colours the pattern by colour symmetry. Checked against the library: the
// pattern each Evolve evolved is read back from the same grammar on a flat scope (the GA's
// seed depends on where Evolve is written, so the lines are kept), laid on the same box
// through the library, and compared vertex by vertex with what the grammar produced.
#include "../box_surface.h"
#include "derive_helpers.h"

#include "runtime/evolve/colour_symmetry.h"
#include "runtime/evolve/surface_ornament.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using namespace fgsg;
namespace ev = fgsg::rt::evolve;

namespace {

// The cube 8 x 8 x 8 (its own polycube at resolution 8), as an OFF file and as a mesh.
std::string variationBoxFile() {
  const std::string path = (std::filesystem::temp_directory_path() / "fgsg_evolve_variation_box.off").string();
  std::ofstream out(path);
  out << "OFF\n8 12 0\n";
  for (int i = 0; i < 8; ++i) out << (i & 1 ? 8 : 0) << ' ' << (i & 2 ? 8 : 0) << ' ' << (i & 4 ? 8 : 0) << '\n';
  for (const auto& q : test::kBoxSideQuads) out << "3 " << q[0] << ' ' << q[1] << ' ' << q[2] << "\n3 " << q[0] << ' ' << q[2] << ' ' << q[3] << '\n';
  return path;
}

rt::surface::SurfaceMesh variationBoxMesh() { return test::boxSurface(rt::Vec3::Zero(), rt::Vec3(8, 8, 8)); }

const std::string kVariationTiles =
    "  locus arc = cubic((0.5, 0), (0.5, 0.276), (0.724, 0.5), (1, 0.5));\n"
    "  locus line = polyline((0, 0.5), (1, 0.5));\n"
    "  section round = polyline((-1, 0), (-0.7, 0.7), (0, 1), (0.7, 0.7), (1, 0));\n"
    "  symbols \"AB\";\n";

// Line 1 declares the surface (or is blank: the flat scope); the Evolve calls stay where
// they are, so their GA seeds are the same in both.
std::string variationGrammar(bool onSurface, const std::string& topExtra, const std::string& sidesExtra) {
  return std::string(onSurface ? "surface torus(2, 0.8);" : "") + "\n" +
         "tileset top {\n" + kVariationTiles + "  faces \"+z\";\n" + topExtra + "}\n" +
         "tileset sides {\n" + kVariationTiles + "  faces \"+x -x +y -y -z\";\n" + sidesExtra + "}\n" +
         "axiom: S(3, 3, 1) Evolve(top, 1, 3, true, 8) Evolve(sides, 1, 3, true, 8)\n";
}

struct VariationRun {
  rt::AssetLibrary assets;
  rt::DeriveResult result;
};

void deriveVariation(VariationRun& run, const std::string& text, const std::string& surface) {
  ir::Module m = fgsg::test::compileText(text);
  rt::DeriveOptions o;
  o.surfaceOverride = surface;
  run.result = backend::interpret(m, o, run.assets);
}

// The pattern the flat run laid for `tileset`: its cells' ornaments in row order,
// "<ornament tileset top A90>" -> A turned once.
ev::AlleleGrid flatPattern(const rt::DeriveResult& r, const std::string& tileset) {
  std::vector<ev::Allele> cells;
  const std::string prefix = "<ornament tileset " + tileset + " ";
  for (const auto& inst : r.instances.instances) {
    const std::string& name = r.instances.assets[inst.asset];
    if (name.rfind(prefix, 0) != 0) continue;
    const char letter = name[prefix.size()];
    const int degrees = std::stoi(name.substr(prefix.size() + 1));
    cells.push_back(ev::Allele{uint8_t(letter - 'A'), uint8_t(degrees / 90)});
  }
  ev::AlleleGrid g(int(std::lround(std::sqrt(double(cells.size())))));
  REQUIRE(g.cells.size() == cells.size());
  g.cells = cells;
  return g;
}

// The world-space positions of the one instance of `asset` in the run.
std::vector<rt::Vec3> placedVertices(VariationRun& run, const std::string& asset) {
  std::string error;
  const int index = run.assets.resolve(asset, error);
  REQUIRE(index >= 0);
  const rt::Mesh& unit = run.assets.mesh(index);
  std::vector<rt::Vec3> out;
  for (const auto& inst : run.result.instances.instances) {
    if (run.result.instances.assets[inst.asset] != asset) continue;
    for (size_t v = 0; v < unit.vertexCount(); ++v)
      out.push_back(fgsg::test::unitPoint(inst, unit.positions[3 * v], unit.positions[3 * v + 1], unit.positions[3 * v + 2]));
  }
  return out;
}

double largestGap(const std::vector<rt::Vec3>& a, const rt::Mesh& b) {
  REQUIRE(a.size() == b.vertexCount());
  double gap = 0;
  for (size_t v = 0; v < a.size(); ++v)
    gap = std::max(gap, (a[v] - rt::Vec3(b.positions[3 * v], b.positions[3 * v + 1], b.positions[3 * v + 2])).norm());
  return gap;
}

}  // namespace

TEST_CASE("Each tileset's pattern goes on the face-lets its faces name", "[evolve][variation]") {
  const std::string box = variationBoxFile();
  VariationRun flat, onBox;
  deriveVariation(flat, variationGrammar(false, "", ""), "");
  deriveVariation(onBox, variationGrammar(true, "", ""), box);
  REQUIRE(flat.result.ok);
  REQUIRE(onBox.result.ok);
  const ev::AlleleGrid top = flatPattern(flat.result, "top"), sides = flatPattern(flat.result, "sides");
  REQUIRE(top.side == 3);
  REQUIRE(sides.side == 3);
  // Two GAs, two seed streams: here they found different patterns.
  CHECK(top != sides);

  const ev::TileSet tiles = ev::exampleTileSet();
  const ev::PolycubeMap map(variationBoxMesh(), ev::PolycubeOptions{0, 8});
  for (const auto& [name, pattern, faces, asset] :
       {std::tuple{"top", top, std::vector<int>{4}, "<surface ornament tileset top 1>"},
        std::tuple{"sides", sides, std::vector<int>{0, 1, 2, 3, 5}, "<surface ornament tileset sides 2>"}}) {
    INFO(name);
    const std::vector<char> shown = ev::faceletsFacing(map, faces);
    std::vector<uint32_t> cells;
    const rt::Mesh whole = ev::surfaceOrnament(tiles, pattern, map, {}, {}, nullptr, 0, &shown, &cells);
    const rt::Mesh expected = ev::partOrnament(whole, cells, std::vector<int>(9, 0), 1)[0];
    CHECK(fgsg::test::countAsset(onBox.result, asset) == 1);
    CHECK(largestGap(placedVertices(onBox, asset), expected) < 1e-4);
  }
}

TEST_CASE("colours L colours the pattern by its symmetry, per instance", "[evolve][variation]") {
  // On the flat scope: generation 2 (9 x 9 cells), colours from generation 1 (3 x 3 blocks).
  // Line 1 is left for the surface, as in variationGrammar.
  const std::string text = "tileset deco {\n" + kVariationTiles + "  colours 1;\n}\n" +
                           "axiom: S(9, 9, 1) Evolve(deco, 2, 3, true)\n";
  VariationRun flat;
  deriveVariation(flat, "\n" + text, "");
  REQUIRE(flat.result.ok);
  const ev::AlleleGrid g = flatPattern(flat.result, "deco");
  REQUIRE(g.side == 9);
  const ev::ColourClasses k = ev::colourClasses(ev::PatternMeasure(ev::exampleTileSet()), g, 3);
  size_t cell = 0;
  for (const auto& inst : flat.result.instances.instances) {
    const std::array<float, 3> want = ev::classColour(k.ofCell[cell++]);
    CHECK(inst.color == want);
  }
  // p4: the corner blocks turn onto each other, one colour.
  CHECK(k.ofCell[0] == k.ofCell[8]);
  CHECK(k.ofCell[0] == k.ofCell[80]);
  CHECK(k.ofCell[0] == k.ofCell[72]);
  // Without `colours` the cells keep the symbol's colour, all alike.
  VariationRun plain;
  deriveVariation(plain, "tileset deco {\n" + kVariationTiles + "\n}\naxiom: S(9, 9, 1) Evolve(deco, 2, 3, true)\n", "");
  REQUIRE(plain.result.ok);
  for (const auto& inst : plain.result.instances.instances) CHECK(inst.color == plain.result.instances.instances[0].color);

  // On the box: a part per colour class, each in its class's colour.
  VariationRun onBox;
  deriveVariation(onBox, "surface torus(2, 0.8);\n" + text, variationBoxFile());
  REQUIRE(onBox.result.ok);
  int parts = 0;
  for (const auto& inst : onBox.result.instances.instances) {
    const std::string& name = onBox.result.instances.assets[inst.asset];
    const std::string prefix = "<surface ornament tileset deco 1 colour ";
    if (name.rfind(prefix, 0) != 0) continue;
    ++parts;
    CHECK(inst.color == ev::classColour(std::stoi(name.substr(prefix.size()))));
  }
  CHECK(parts == k.classCount);

  // A colour generation past the pattern's is R025 at Evolve.
  VariationRun bad;
  deriveVariation(bad, "tileset deco {\n" + kVariationTiles + "  colours 3;\n}\naxiom: S(9, 9, 1) Evolve(deco, 2, 3, true)\n", "");
  REQUIRE_FALSE(bad.result.ok);
  CHECK(bad.result.messages[0].code == "R025");
  CHECK_THAT(bad.result.messages[0].message, Catch::Contains("past the pattern's generation 2"));
}

TEST_CASE("A tileset's faces item is checked where it is written", "[evolve][variation][errors]") {
  auto rejected = [](const std::string& item, const std::string& part) {
    const std::string text = "tileset t {\n" + kVariationTiles + "  " + item + "\n}\naxiom: Evolve(t, 1)\n";
    CHECK_THROWS_WITH(fgsg::test::compileText(text), Catch::Contains("E041") && Catch::Contains(part) &&
                                                         Catch::Contains("test.fgsg:6:"));
  };
  rejected("faces \"+z up\";", "unknown direction 'up'");
  rejected("faces \"+z,+z\";", "direction '+z' is listed twice");
  rejected("faces 4;", "'faces' is one constant string");
  rejected("faces \" \";", "'faces' names no direction");
  rejected("colours 13;", "'colours' takes whole numbers from 0 to 12");
  CHECK_NOTHROW(fgsg::test::compileText("tileset t {\n" + kVariationTiles +
                                         "  faces \"+x, -x +y\";\n  colours 0;\n}\naxiom: Evolve(t, 1)\n"));
}
