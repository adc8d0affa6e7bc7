// Building lots from mesh faces: each OBJ, PLY or OFF polygon one lot, kept whole (never
// triangulated), seen from above ((x, y, z) at (x, -z)) and counter-clockwise, and every
// unsound face refused with a message naming the file, the face and its corners.
#include "runtime/io/mesh_lots.h"
#include "scratch_files.h"

#include "runtime/planar.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

using namespace fgsg::rt;
namespace fs = std::filesystem;

namespace {

// Positive counter-clockwise.
double signedArea(const std::vector<Eigen::Vector2d>& ring) { return twiceRingArea(ring) / 2; }

std::string write(const std::string& name, const std::string& bytes) {
  static int n = 0;
  const fs::path dir = fgsg::test::scratchDir("mesh_lots", std::to_string(n++));
  std::ofstream(dir / name, std::ios::binary) << bytes;
  return (dir / name).string();
}

std::vector<Lot> lotsOf(const std::string& name, const std::string& bytes) {
  std::vector<Lot> lots;
  std::string error;
  const bool ok = readMeshLots(write(name, bytes), lots, error);
  INFO(error);
  CHECK(ok);
  return lots;
}

// The error for a file that must not read, checked to start with its path, without it.
std::string refusal(const std::string& name, const std::string& bytes) {
  const std::string path = write(name, bytes);
  std::vector<Lot> lots(1);
  std::string error;
  CHECK_FALSE(readMeshLots(path, lots, error));
  CHECK(lots.empty());
  REQUIRE(error.rfind(path, 0) == 0);
  return error.substr(path.size());
}

std::string plyHeader(const std::string& format, int vertices, int faces) {
  return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(faces) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

}  // namespace

TEST_CASE("an OBJ face of six corners stays one lot, its corners at (x, -z)", "[mesh_lots]") {
  // An L: 20 by 18 with an 11 by 9 notch, north being -z, at varying heights (y is
  // ignored); then a quad whose corners are counted back from the last vertex.
  const std::vector<Lot> lots = lotsOf("lots.obj", R"(# two lots
o block
v 0 0 0
v 20 1 0
v 20 2 -9
v 9 3 -9
v 9 4 -18
v 0 5 -18
vt 0 0
vn 0 1 0
f 1 2/1 3//1 4/1/1 5 6
v 30 0 0
v 42 0 0
v 42 0 -10
v 30 0 -10
f -4/1/1 -3/1/1 -2/1/1 -1/1/1
)");
  REQUIRE(lots.size() == 2);
  const std::vector<Eigen::Vector2d> l{{0, 0}, {20, 0}, {20, 9}, {9, 9}, {9, 18}, {0, 18}};
  CHECK(lots[0].outer == l);
  CHECK(signedArea(lots[0].outer) == 20 * 18 - 11 * 9);
  const std::vector<Eigen::Vector2d> quad{{30, 0}, {42, 0}, {42, 10}, {30, 10}};
  CHECK(lots[1].outer == quad);
  CHECK(signedArea(lots[1].outer) == 12 * 10);
  for (size_t i = 0; i < lots.size(); ++i) {
    CHECK(lots[i].feature == i);
    CHECK(lots[i].part == 0);
    CHECK(lots[i].id.empty());
    CHECK(lots[i].holes.empty());
    CHECK(lots[i].numbers.empty());
    CHECK(lots[i].strings.empty());
  }
  // z = 0 gives north +0, not -0 (which would print as "-0" downstream).
  CHECK_FALSE(std::signbit(lots[0].outer[0].y()));
}

TEST_CASE("a face running clockwise seen from above is turned, its first corner kept first", "[mesh_lots]") {
  // Facing down: (0, 0) -> (0, 10) -> (10, 10) -> (10, 0) on the ground.
  const std::vector<Lot> lots = lotsOf("down.obj", "v 0 0 0\nv 0 0 -10\nv 10 0 -10\nv 10 0 0\nf 1 2 3 4\n");
  REQUIRE(lots.size() == 1);
  const std::vector<Eigen::Vector2d> turned{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  CHECK(lots[0].outer == turned);
  CHECK(signedArea(lots[0].outer) == 100.0);
}

TEST_CASE("corners repeated in a row or closing the face are dropped", "[mesh_lots]") {
  // Vertices 5 and 6 sit where 1 and 2 do: the outline 1 2 6 3 4 5 is the square 1 2 3 4.
  const std::vector<Lot> lots =
      lotsOf("closed.obj", "v 0 0 0\nv 6 0 0\nv 6 0 -3\nv 0 0 -3\nv 0 1 0\nv 6 2 0\nf 1 2 6 3 4 5\n");
  REQUIRE(lots.size() == 1);
  const std::vector<Eigen::Vector2d> rectangle{{0, 0}, {6, 0}, {6, 3}, {0, 3}};
  CHECK(lots[0].outer == rectangle);
}

TEST_CASE("coordinates come out as the file wrote them, not rounded to single precision", "[mesh_lots]") {
  const std::vector<Lot> lots =
      lotsOf("decimals.obj", "v 0.1 0 -0.2\nv 12.3 0 -0.2\nv 12.3 0 -4.7\nf 1 2 3\n");
  REQUIRE(lots.size() == 1);
  const std::vector<Eigen::Vector2d> triangle{{0.1, 0.2}, {12.3, 0.2}, {12.3, 4.7}};
  CHECK(lots[0].outer == triangle);
}

TEST_CASE("a PLY pentagon is one lot, in ASCII and in binary", "[mesh_lots]") {
  // The fifth vertex is in no face.
  const std::string ascii = plyHeader("ascii", 6, 1) +
                            "0 0 0\n10 0 0\n12 0 -6\n5 0 -10\n7 7 7\n-2 0 -6\n"
                            "5 0 1 2 3 5\n";
  const std::vector<Eigen::Vector2d> pentagon{{0, 0}, {10, 0}, {12, 6}, {5, 10}, {-2, 6}};
  // Shoelace: (0 + 60 + 90 + 50 + 0) / 2.
  const double area = 100;
  std::vector<Lot> lots = lotsOf("pentagon.ply", ascii);
  REQUIRE(lots.size() == 1);
  CHECK(lots[0].outer == pentagon);
  CHECK(signedArea(lots[0].outer) == area);

  std::string binary = plyHeader("binary_little_endian", 6, 1);
  for (const double v : {0., 0., 0., 10., 0., 0., 12., 0., -6., 5., 0., -10., 7., 7., 7., -2., 0., -6.}) {
    char bytes[8];
    std::memcpy(bytes, &v, 8);  // the test machines are little-endian, as the format
    binary.append(bytes, 8);
  }
  binary += char(5);
  for (const int32_t i : {0, 1, 2, 3, 5}) {
    char bytes[4];
    std::memcpy(bytes, &i, 4);
    binary.append(bytes, 4);
  }
  lots = lotsOf("pentagon_binary.ply", binary);
  REQUIRE(lots.size() == 1);
  CHECK(lots[0].outer == pentagon);
}

TEST_CASE("an OFF file gives its faces as lots too", "[mesh_lots]") {
  const std::vector<Lot> lots = lotsOf("lots.off", "OFF\n4 1 0\n0 0 0\n4 0 0\n4 0 -2\n0 0 -2\n4 0 1 2 3\n");
  REQUIRE(lots.size() == 1);
  CHECK(signedArea(lots[0].outer) == 8.0);
}

TEST_CASE("a face that crosses itself seen from above is refused naming the face and the edges",
          "[mesh_lots]") {
  // A bow tie: the first and third edges cross at (5, 5) on the ground.
  CHECK(refusal("bowtie.obj", "v 0 0 0\nv 10 0 -10\nv 10 0 0\nv 0 0 -10\nf 1 2 3 4\n") ==
        ": face 0: the edge from corner 2 (10, 0, 0) to corner 3 (0, 0, -10) crosses the edge from corner 0 "
        "(0, 0, 0) to corner 1 (10, 0, -10)");
  // The second face of the file is named, with its corners as written.
  CHECK(refusal("second.obj", "v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nf 1 2 3 4\nf 1 3 2 4\n") ==
        ": face 1: the edge from corner 2 (1, 0, 0) to corner 3 (0, 0, -1) crosses the edge from corner 0 "
        "(0, 0, 0) to corner 1 (1, 0, -1)");
}

TEST_CASE("a face without area seen from above is refused", "[mesh_lots]") {
  // A wall: all its corners over one line on the ground.
  CHECK(refusal("wall.obj", "v 0 0 0\nv 5 0 0\nv 5 3 0\nv 0 3 0\nf 1 2 3 4\n") ==
        ": face 0: zero area seen from above (all its corners on one line, from corner 0 (0, 0, 0))");
  CHECK(refusal("line.ply", plyHeader("ascii", 3, 1) + "0 0 0\n1 0 -1\n2 0 -2\n3 0 1 2\n") ==
        ": face 0: zero area seen from above (all its corners on one line, from corner 0 (0, 0, 0))");
}

TEST_CASE("an OBJ face naming a vertex twice is refused by its line", "[mesh_lots]") {
  const std::string square = "v 0 0 0\nv 4 0 0\nv 4 0 -4\nv 0 0 -4\nv 2 0 -2\n";
  CHECK(refusal("pinched.obj", square + "f 1 2 3\nf 1 2 5 3 4 5\n") ==
        ":7: face 1: corners 2 and 5 are both vertex 5, so its outline touches itself");
  CHECK(refusal("flat.obj", square + "f 1 2 1\n") ==
        ":6: face 0: 2 distinct vertices; a lot needs at least 3");
}

TEST_CASE("a mesh without polygon faces is refused", "[mesh_lots]") {
  CHECK(refusal("empty.obj", "") == ": the file is empty (no faces)");
  CHECK(refusal("points.obj", "v 0 0 0\nv 1 0 0\nv 1 0 -1\np 1 2 3\nl 1 2\n") ==
        ": no faces of three or more corners to take lots from");
  CHECK(refusal("points.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nend_header\n0 0 0\n1 0 0\n0 0 1\n") ==
        ": no faces of three or more corners to take lots from");
}

TEST_CASE("a missing file or one of another format is refused with its name", "[mesh_lots]") {
  std::vector<Lot> lots;
  std::string error;
  CHECK_FALSE(readMeshLots("/nonexistent/fgsg/lots.obj", lots, error));
  CHECK(error.rfind("/nonexistent/fgsg/lots.obj: ", 0) == 0);
  CHECK_FALSE(readMeshLots("/nonexistent/fgsg/lots.stl", lots, error));
  CHECK(error ==
        "/nonexistent/fgsg/lots.stl: lots are read from .obj, .ply or .off meshes, not from '.stl' files");
  CHECK(isMeshLotsPath("a/b/LOTS.Obj"));
  CHECK(isMeshLotsPath("lots.ply"));
  CHECK_FALSE(isMeshLotsPath("lots.geojson"));
}
