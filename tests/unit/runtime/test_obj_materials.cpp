// Textured meshes as OBJ: the faces of each texture run follow its `usemtl`, the OBJ names
// a .mtl beside it with `mtllib`, and that file, staged in the same transaction, gives each
// texture's image as `map_Kd` relative to its folder. An untextured mesh gives no .mtl
// and the bytes it always had.
#include "runtime/io/output_transaction.h"
#include "runtime/io/write_mesh.h"

#include <catch2/catch.hpp>

#include "scratch_files.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace fgsg::rt;
namespace fs = std::filesystem;

namespace {

using fgsg::test::readFile;

// Two unit quads side by side, facing +z, each two triangles with the full image on it:
// the first untextured, the second with texture `texture` (when `texture` >= 0; none
// listed when textures is empty).
Mesh twoQuads(std::vector<std::string> textures, int32_t texture) {
  Mesh m;
  for (float x0 : {0.0f, 2.0f}) {
    const uint32_t first = uint32_t(m.vertexCount());
    const float corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& c : corners) {
      m.positions.insert(m.positions.end(), {x0 + c[0], c[1], 0});
      m.normals.insert(m.normals.end(), {0, 0, 1});
      m.texcoords.insert(m.texcoords.end(), {c[0], c[1]});
    }
    m.indices.insert(m.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  }
  m.textures = std::move(textures);
  if (!m.textures.empty()) m.textureRuns = {{0, -1}, {2, texture}};
  return m;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The lines that are not vertex data (v, vt, vn): the header, materials and faces.
std::vector<std::string> structureLines(const std::string& obj) {
  std::vector<std::string> out;
  for (const auto& line : lines(obj))
    if (line.rfind("v", 0) != 0) out.push_back(line);
  return out;
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string material(const std::string& name) {
  return "\nnewmtl " + name + "\nKd 1 1 1\nKa 0 0 0\nKs 0 0 0\nd 1\nillum 1\n";
}

}  // namespace

TEST_CASE("a textured OBJ groups its faces by material and names a .mtl with the images", "[writers][obj]") {
  const fs::path dir = fgsg::test::scratchDir("obj_materials", "textured");
  fs::create_directories(dir / "images");
  fs::create_directories(dir / "out");
  const fs::path brick = dir / "images" / "brick wall.png", roof = dir / "out" / "roof.png";
  std::ofstream(brick) << "png";
  std::ofstream(roof) << "png";
  const Mesh mesh = twoQuads({brick.string(), roof.string()}, 1);
  std::string error;

  SECTION("writeMesh writes both files") {
    REQUIRE(io::writeMesh(mesh, (dir / "out" / "mesh.obj").string(), error));
    CHECK(filesIn(dir / "out") == std::vector<std::string>{"mesh.mtl", "mesh.obj", "roof.png"});
    const std::string obj = readFile(dir / "out" / "mesh.obj");
    CHECK(structureLines(obj) == std::vector<std::string>{"# fgsg", "mtllib mesh.mtl", "usemtl fgsg_plain",
                                                          "f 1/1/1 2/2/2 3/3/3", "f 1/1/1 3/3/3 4/4/4",
                                                          "usemtl fgsg_texture_1", "f 5/5/5 6/6/6 7/7/7",
                                                          "f 5/5/5 7/7/7 8/8/8"});
    CHECK(lines(obj).size() == 8 + 3 * 8);  // v, vt and vn for each of the 8 vertices
    // Paths relative to the .mtl's folder, spaces as they are.
    CHECK(readFile(dir / "out" / "mesh.mtl") ==
          "# fgsg\n" + material("fgsg_plain") + material("fgsg_texture_0") +
              "map_Kd ../images/brick wall.png\n" + material("fgsg_texture_1") + "map_Kd roof.png\n");

    // encodeMesh's bytes are the file's without the mtllib line (no file beside them).
    std::string bytes;
    REQUIRE(io::encodeMesh(mesh, ".obj", bytes, error));
    std::string withoutMtllib = obj;
    withoutMtllib.erase(withoutMtllib.find("mtllib mesh.mtl\n"), std::string("mtllib mesh.mtl\n").size());
    CHECK(bytes == withoutMtllib);
  }

  SECTION("the .mtl is staged in the OBJ's transaction and appears with it on commit") {
    io::OutputTransaction outputs;
    REQUIRE(io::stageMesh(mesh, (dir / "out" / "Scene.OBJ").string(), outputs, error));
    CHECK(filesIn(dir / "out").size() == 3);  // two temporaries and roof.png, no targets yet
    CHECK_FALSE(fs::exists(dir / "out" / "Scene.mtl"));
    REQUIRE(outputs.commit(error));
    CHECK(filesIn(dir / "out") == std::vector<std::string>{"Scene.OBJ", "Scene.mtl", "roof.png"});
    CHECK(lines(readFile(dir / "out" / "Scene.OBJ"))[1] == "mtllib Scene.mtl");
  }

  SECTION("a transaction dropped before commit leaves neither file") {
    {
      io::OutputTransaction outputs;
      REQUIRE(io::stageMesh(mesh, (dir / "out" / "mesh.obj").string(), outputs, error));
    }
    CHECK(filesIn(dir / "out") == std::vector<std::string>{"roof.png"});
  }

  SECTION("consecutive runs with one texture share one usemtl") {
    Mesh same = mesh;
    same.textureRuns = {{0, 1}, {1, 1}, {2, -1}, {3, -1}};
    REQUIRE(io::writeMesh(same, (dir / "out" / "same.obj").string(), error));
    CHECK(structureLines(readFile(dir / "out" / "same.obj")) ==
          std::vector<std::string>{"# fgsg", "mtllib same.mtl", "usemtl fgsg_texture_1",
                                   "f 1/1/1 2/2/2 3/3/3", "f 1/1/1 3/3/3 4/4/4", "usemtl fgsg_plain",
                                   "f 5/5/5 6/6/6 7/7/7", "f 5/5/5 7/7/7 8/8/8"});
  }

  SECTION("an empty run writes no usemtl, and segments after plain faces need none") {
    // Run 0 (texture 0) ends where it starts; the segments follow plain faces, which
    // already use fgsg_plain. Both were survivors of the mutation run (#51): a stray
    // 'usemtl fgsg_texture_0' with no face, a second 'usemtl fgsg_plain' before 'l'.
    Mesh runs = mesh;
    runs.textureRuns = {{0, 0}, {0, 1}, {2, -1}};
    runs.lines = {0, 4};
    REQUIRE(io::writeMesh(runs, (dir / "out" / "runs.obj").string(), error));
    CHECK(structureLines(readFile(dir / "out" / "runs.obj")) ==
          std::vector<std::string>{"# fgsg", "mtllib runs.mtl", "usemtl fgsg_texture_1",
                                   "f 1/1/1 2/2/2 3/3/3", "f 1/1/1 3/3/3 4/4/4", "usemtl fgsg_plain",
                                   "f 5/5/5 6/6/6 7/7/7", "f 5/5/5 7/7/7 8/8/8", "l 1 5"});
  }

  SECTION("other formats get no .mtl") {
    REQUIRE(io::writeMesh(mesh, (dir / "mesh.ply").string(), error));
    CHECK(filesIn(dir) == std::vector<std::string>{"images", "mesh.ply", "out"});
  }
}

TEST_CASE("an untextured OBJ has no materials and the bytes encodeMesh gives", "[writers][obj]") {
  const fs::path dir = fgsg::test::scratchDir("obj_materials", "untextured");
  const Mesh mesh = twoQuads({}, -1);
  REQUIRE_FALSE(mesh.textured());
  std::string error, bytes;
  REQUIRE(io::writeMesh(mesh, (dir / "mesh.obj").string(), error));
  REQUIRE(io::encodeMesh(mesh, ".obj", bytes, error));
  CHECK(filesIn(dir) == std::vector<std::string>{"mesh.obj"});
  CHECK(readFile(dir / "mesh.obj") == bytes);
  CHECK(structureLines(bytes) == std::vector<std::string>{"# fgsg", "f 1/1/1 2/2/2 3/3/3",
                                                          "f 1/1/1 3/3/3 4/4/4", "f 5/5/5 6/6/6 7/7/7",
                                                          "f 5/5/5 7/7/7 8/8/8"});
}

TEST_CASE("runs longer than a formatting block keep their faces in order", "[writers][obj]") {
  // Faces are formatted in blocks of 16Ki lines on all cores; runs cut across blocks.
  Mesh mesh;
  constexpr uint32_t kTriangles = 100000;
  for (uint32_t v = 0; v < kTriangles + 2; ++v) mesh.positions.insert(mesh.positions.end(), {float(v), 0, 0});
  for (uint32_t t = 0; t < kTriangles; ++t) mesh.indices.insert(mesh.indices.end(), {t, t + 1, t + 2});
  std::string error, plain, textured;
  REQUIRE(io::encodeMesh(mesh, ".obj", plain, error));
  mesh.textures = {"a.png", "b.png"};
  mesh.textureRuns = {{0, -1}, {40000, 1}, {70001, -1}};
  REQUIRE(io::encodeMesh(mesh, ".obj", textured, error));
  std::vector<std::string> expected = lines(plain);
  const size_t firstFace = expected.size() - kTriangles;
  expected.insert(expected.begin() + ptrdiff_t(firstFace + 70001), "usemtl fgsg_plain");
  expected.insert(expected.begin() + ptrdiff_t(firstFace + 40000), "usemtl fgsg_texture_1");
  expected.insert(expected.begin() + ptrdiff_t(firstFace), "usemtl fgsg_plain");
  CHECK(lines(textured) == expected);
}
