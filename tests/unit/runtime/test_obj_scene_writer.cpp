// The grouped OBJ of a scene (runtime/output/obj_scene_writer.h): `o` per start shape,
// `g` per group (none under GroupBy::None), `usemtl` where the material changes, indices
// counted over the whole file (v, vt and vn each in its own list), and the .mtl of exactly the materials used, in the order
// of first use. A scene of two start shapes built by hand, its text written out in full.
#include "runtime/output/obj_scene_writer.h"

#include "runtime/io/byte_sink.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

using namespace fgsg::rt;
using namespace fgsg::rt::output;

namespace {

Material material(std::array<float, 3> color, int32_t image, bool vertexColors, const char* name) {
  Material m;
  m.color = color, m.image = image, m.vertexColors = vertexColors, m.name = name;
  return m;
}

// Lot "lot A": a red wall quad (normals, no texcoords) and a roof of two triangles, the
// first on the brick image, the second red; lot "B": one triangle coloured per vertex and
// a line segment. Material 3 is used by nothing.
Scene tinyScene(GroupBy by) {
  Scene s;
  s.groupBy = by;
  s.instancing = Instancing::Off;
  s.images = {"/nowhere/city/tex/brick.png"};
  s.materials = {material({1, 0, 0}, -1, false, "ff0000"), material({1, 1, 1}, -1, true, "vertex_colors"),
                 material({1, 1, 1}, 0, false, "brick_ffffff"), material({0, 0, 1}, -1, false, "0000ff")};

  BakedPart wall;
  wall.mesh.positions = {0, 0, 0, 2, 0, 0, 2, 3, 0, 0, 3, 0};
  wall.mesh.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  wall.mesh.indices = {0, 1, 2, 0, 2, 3};
  wall.materials = {0};
  BakedPart roof;
  roof.mesh.positions = {0, 3, 0, 2, 3, 0, 1, 4, 0.5f, 0, 4, 0};
  roof.mesh.normals = {0, 0.6f, 0.8f, 0, 0.6f, 0.8f, 0, 0.6f, 0.8f, 0, 0.6f, 0.8f};
  roof.mesh.texcoords = {0, 0, 1, 0, 0.5f, 1, 0, 1};
  roof.mesh.indices = {0, 1, 2, 0, 2, 3};
  roof.mesh.textures = {"/nowhere/city/tex/brick.png"};
  roof.mesh.textureRuns = {{0, 0}, {1, -1}};
  roof.materials = {2, 0};  // per image, then the untextured one
  BakedPart painted;
  painted.mesh.positions = {10, 0, 0, 11, 0, 0, 10, 1, 0};
  painted.mesh.colors = {0.5f, 0.25f, 1, 1, 0, 0, 0, 1, 0};
  painted.mesh.indices = {0, 1, 2};
  painted.mesh.lines = {0, 1};
  painted.materials = {1};

  StartNode a;
  a.info.name = "lot A";
  a.index = 0;
  a.groups.resize(2);
  a.groups[0].name = "Wall";
  a.groups[0].baked.push_back(std::move(wall));
  a.groups[1].name = "Roof tile";
  a.groups[1].baked.push_back(std::move(roof));
  StartNode b;
  b.info.name = "B";
  b.index = 1;
  b.groups.resize(1);
  b.groups[0].name = "Wall";
  b.groups[0].baked.push_back(std::move(painted));
  s.starts = {std::move(a), std::move(b)};
  return s;
}

const char* const kObj =
    "# fgsg\n"
    "mtllib city.mtl\n"
    "o lot_A\n"
    "g Wall\n"
    "v 0 0 0 1 1 1\n"  // the file has vertex colours: white where a part has none
    "v 2 0 0 1 1 1\n"
    "v 2 3 0 1 1 1\n"
    "v 0 3 0 1 1 1\n"
    "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
    "usemtl ff0000\n"
    "f 1//1 2//2 3//3\n"
    "f 1//1 3//3 4//4\n"
    "g Roof_tile\n"
    "v 0 3 0 1 1 1\n"
    "v 2 3 0 1 1 1\n"
    "v 1 4 0.5 1 1 1\n"
    "v 0 4 0 1 1 1\n"
    "vt 0 0\nvt 1 0\nvt 0.5 1\nvt 0 1\n"
    "vn 0 0.6 0.8\nvn 0 0.6 0.8\nvn 0 0.6 0.8\nvn 0 0.6 0.8\n"
    "usemtl brick_ffffff\n"
    "f 5/1/5 6/2/6 7/3/7\n"  // vt counts its own lines: the wall wrote none
    "usemtl ff0000\n"
    "f 5/1/5 7/3/7 8/4/8\n"
    "o B\n"
    "g Wall\n"
    "v 10 0 0 0.5 0.25 1\n"
    "v 11 0 0 1 0 0\n"
    "v 10 1 0 0 1 0\n"
    "usemtl vertex_colors\n"
    "f 9 10 11\n"
    "l 9 10\n";

std::string objText(const Scene& s, const std::string& mtl) {
  std::string text, error;
  io::StringSink sink(text);
  REQUIRE(writeObjScene(s, sink, mtl, error));
  REQUIRE(sink.flush());
  CHECK(error.empty());
  return text;
}

}  // namespace

TEST_CASE("the OBJ of a scene has an o per start shape, a g per group, usemtl per material", "[output]") {
  CHECK(objText(tinyScene(GroupBy::Symbol), "city.mtl") == kObj);
}

TEST_CASE("the OBJ of a scene without groups has no g lines and, without a .mtl, no mtllib", "[output]") {
  std::string expected;
  std::istringstream lines(kObj);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("g ", 0) != 0 && line.rfind("mtllib ", 0) != 0) expected += line + "\n";
  CHECK(objText(tinyScene(GroupBy::None), "") == expected);
}

TEST_CASE("the .mtl of a scene defines the materials used, in order of first use, images relative", "[output]") {
  const std::string common = "Ka 0 0 0\nKs 0 0 0\nd 1\nillum 1\nPr 0.8\nPm 0\n";
  CHECK(mtlSceneText(tinyScene(GroupBy::Symbol), "/nowhere/city") ==
        "# fgsg\n"
        "\nnewmtl ff0000\nKd 1 0 0\n" + common +
        "\nnewmtl brick_ffffff\nKd 1 1 1\n" + common + "map_Kd tex/brick.png\n"
        "\nnewmtl vertex_colors\nKd 1 1 1\n" + common);
}

TEST_CASE("the OBJ of a scene refuses instances and vertices that are not finite", "[output]") {
  std::string text, error;
  io::StringSink sink(text);
  Scene instanced = tinyScene(GroupBy::Symbol);
  static const Mesh unit;
  instanced.meshes.push_back({&unit, "piece", "piece", {0, 0}, 1});
  instanced.starts[1].groups[0].instanced.push_back({0, 0, {0}, {Trs{}}, {{1, 0, 0}}});
  CHECK_FALSE(writeObjScene(instanced, sink, "", error));
  CHECK(error == "an OBJ has no instances: build its scene with --instancing off");
  Scene broken = tinyScene(GroupBy::Symbol);
  broken.starts[1].groups[0].baked[0].mesh.positions[4] = NAN;
  CHECK_FALSE(writeObjScene(broken, sink, "", error));
  CHECK(error == "a vertex of 'B' is not finite");
}
