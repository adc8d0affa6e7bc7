// Mesh files read as they are: forged counts fail at once with the file and line (nothing
// is allocated by a count the file cannot hold), comments are skipped anywhere in OFF.
#include "runtime/io/read_mesh_file.h"
#include "scratch_files.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

using namespace fgsg::rt::io;
namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& bytes) {
  static int n = 0;
  const fs::path dir = fgsg::test::scratchDir("read_mesh_file", std::to_string(n++));
  std::ofstream(dir / name, std::ios::binary) << bytes;
  return (dir / name).string();
}

// The error for a file that must not read, checked to start with its path.
std::string errorOf(const std::string& name, const std::string& bytes) {
  const std::string path = write(name, bytes);
  MeshFileContent m;
  std::string error;
  CHECK_FALSE(readMeshFile(path, m, error));
  CHECK(m.vertices.empty());
  CHECK(m.polygonCount() == 0);
  CHECK(error.rfind(path, 0) == 0);
  return error.substr(path.size());
}

MeshFileContent read(const std::string& name, const std::string& bytes) {
  MeshFileContent m;
  std::string error;
  const bool ok = readMeshFile(write(name, bytes), m, error);
  INFO(error);
  CHECK(ok);
  return m;
}

std::string plyHeader(const std::string& format, const std::string& faceList, long faces) {
  return "ply\nformat " + format + " 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face " + std::to_string(faces) + "\nproperty list " + faceList +
         " vertex_indices\nend_header\n";
}

}  // namespace

TEST_CASE("OFF: comments, keyword variants, extra columns", "[read_mesh_file]") {
  // A comment after the counts (CGAL's cube_poly.off), after numbers, and before the keyword.
  auto m = read("c.off", "# made by hand\nOFF # keyword\n3 1 0\n# comment\n0 0 0\n1 0 0 #x\n"
                         "\n0 1 0\n3 0 1 2 # the face\n");
  REQUIRE(m.vertices.size() == 3);
  CHECK(m.vertices[1] == std::array<double, 3>{1, 0, 0});
  REQUIRE(m.polygonCount() == 1);
  CHECK(m.corners == std::vector<int>{0, 1, 2});
  // Counts on the keyword's line; colours after coordinates and indices; a quad.
  m = read("q.off", "COFF 4 1 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n1 1 0 1 0 0 1\n0 1 0 1 0 0 1\n"
                    "4 0 1 2 3 255 0 0\n");
  CHECK(m.vertices.size() == 4);
  CHECK(m.cornerCount(0) == 4);
  // Homogeneous coordinates divide by w; nOFF names its dimension.
  m = read("h.off", "4OFF\n3 1 0\n0 0 0 2\n2 0 0 2\n0 4 0 2\n3 0 1 2\n");
  CHECK(m.vertices[2] == std::array<double, 3>{0, 2, 0});
  // Every coordinate, z included, is divided by w: (2 4 6) / 2.
  m = read("hz.off", "4OFF\n3 1 0\n2 4 6 2\n0 0 0 1\n1 0 0 1\n3 0 1 2\n");
  CHECK(m.vertices[0] == std::array<double, 3>{1, 2, 3});
  m = read("n.off", "nOFF\n4\n3 1 0\n0 0 0 9\n1 0 0 9\n0 1 0 9\n3 0 1 2\n");
  CHECK(m.vertices[1] == std::array<double, 3>{1, 0, 0});
}

TEST_CASE("OFF: forged and broken files fail at once with the line", "[read_mesh_file]") {
  CHECK(errorOf("h.off", "OFF\n") == ": the file ends before the vertex and face counts");
  CHECK(errorOf("n.off", "OFF\n-1 0 0\n") == ":2: the vertex count -1 is negative");
  CHECK(errorOf("f.off", "OFF\n0 -4 0\n") == ":2: the face count -4 is negative");
  CHECK(errorOf("w.off", "OFF\nthree 1 0\n") == ":2: the vertex count 'three' is not a whole number");
  CHECK(errorOf("big.off", "OFF\n1000000000 0 0\n0 0 0\n") ==
        ":2: the header declares 1000000000 vertices and 0 faces, more than the 6 bytes after "
        "it can hold");
  CHECK(errorOf("big2.off", "OFF\n3 99999999999999999999 0\n0 0 0\n") ==
        ":2: the face count '99999999999999999999' is not a whole number");
  CHECK(errorOf("c.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n") ==
        ":6: face 0 has -3 corners (a face needs at least 3)");
  CHECK(errorOf("two.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n# long enough\n") ==
        ":6: face 0 has 2 corners (a face needs at least 3)");
  // nOFF's dimension is at least 3; dimension 2 would read x y only (the file fits it).
  CHECK(errorOf("n2.off", "nOFF\n2\n3 1 0\n0 0\n1 0\n0 1\n3 0 1 2\n") ==
        ":2: nOFF needs a dimension between 3 and 16 after the keyword");
  CHECK(errorOf("l.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n") ==
        ":6: face 0 lists 2000000000 corners, but the line holds only 3 numbers after the count");
  CHECK(errorOf("i.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n") ==
        ":6: face 0 refers to vertex 3, but there are only 3 vertices");
  CHECK(errorOf("e.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# long enough\n") ==
        ": the file ends after 1 of 2 faces");
  CHECK(errorOf("v.off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n# long enough\n") ==
        ":4: vertex 1 has 2 coordinates, expected 3");
  CHECK(errorOf("x.off", "OFF\n3 1 0\n0 0 0\n1 0 z\n0 1 0\n3 0 1 2\n") ==
        ":4: vertex coordinate 'z' is not a number");
  CHECK(errorOf("nan.off", "OFF\n3 1 0\n0 0 0\n1 0 NaN\n0 1 0\n3 0 1 2\n") ==
        ":4: vertex coordinate 'NaN' is not a finite number");
  CHECK(errorOf("k.off", "solid\n") ==
        ":1: cannot read the file: it does not start with an OFF keyword (OFF, COFF, NOFF, "
        "4OFF, ...), found 'solid'");
  CHECK(errorOf("b.off", "OFF BINARY\n") ==
        ":1: binary OFF is not supported (save the mesh as text OFF or PLY)");
  CHECK(errorOf("z.off", "") == ": the file is empty (no faces)");
}

TEST_CASE("PLY: counts are checked against the bytes before OpenMesh reads",
          "[read_mesh_file]") {
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::string vertices(reinterpret_cast<const char*>(v), sizeof v);
  const auto face = [](int32_t n) {
    std::string s(reinterpret_cast<const char*>(&n), 4);
    for (int32_t i : {0, 1, 2}) s.append(reinterpret_cast<const char*>(&i), 4);
    return s;
  };
  // Sound: read.
  auto m = read("ok.ply", plyHeader("binary_little_endian", "int int", 1) + vertices + face(3));
  CHECK(m.vertices.size() == 3);
  CHECK(m.corners == std::vector<int>{0, 1, 2});
  // A face list claiming 2^30 items, and a negative one: OpenMesh would size a buffer by it.
  CHECK(errorOf("l.ply", plyHeader("binary_little_endian", "int int", 1) + vertices +
                             face(1 << 30)) ==
        ": face element 0 has a 'vertex_indices' list of 1073741824 items, more than the rest "
        "of the file holds");
  CHECK(errorOf("neg.ply", plyHeader("binary_little_endian", "int int", 1) + vertices + face(-3)) ==
        ": face element 0 has a 'vertex_indices' list of -3 items, more than the rest of the "
        "file holds");
  // More faces declared than stored.
  CHECK(errorOf("t.ply", plyHeader("binary_little_endian", "int int", 2) + vertices + face(3)) ==
        ": the file ends inside face element 1 (the header declares 2)");
  CHECK(errorOf("h.ply", plyHeader("binary_little_endian", "int int", 2000000000) + vertices) ==
        ":7: the header declares 2000000000 face elements, more than the 36 bytes after the "
        "header can hold");
  CHECK(errorOf("a.ply", plyHeader("ascii", "uchar int", 1) + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n") ==
        ": face element 0 has a 'vertex_indices' list of '200' items (not a whole number the "
        "rest of the file can hold)");
  CHECK(errorOf("e.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n") ==
        ": the PLY header has no 'end_header' line");
  CHECK(errorOf("c.ply", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n") ==
        ":3: element 'vertex' has the count '-3' (not a whole number of at least 0)");
  CHECK(errorOf("i.ply", plyHeader("binary_little_endian", "int int", 1) + vertices + [] {
          std::string s = "\x03";
          s.pop_back();
          int32_t n = 3, a = 0, b = 1, c = 7;
          for (int32_t x : {n, a, b, c}) s.append(reinterpret_cast<const char*>(&x), 4);
          return s;
        }()) == ": face 0 refers to vertex 7, but there are only 3 vertices");
  // One past the last vertex: OpenMesh hands it over unchecked.
  CHECK(errorOf("n.ply", plyHeader("ascii", "uchar int", 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n") ==
        ": face 0 refers to vertex 3, but there are only 3 vertices");
}

TEST_CASE("OBJ: an index out of range is named as the file spells it", "[read_mesh_file]") {
  CHECK(errorOf("i.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n") ==
        ": face 0 refers to vertex 9, but there are only 3 vertices (counting from 1)");
  // One past the last vertex: OpenMesh hands it over unchecked.
  CHECK(errorOf("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n") ==
        ": face 0 refers to vertex 4, but there are only 3 vertices (counting from 1)");
  const auto m = read("ok.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -1\n");
  CHECK(m.corners == std::vector<int>{0, 1, 2});
}

TEST_CASE("OBJ files read from many threads at once", "[read_mesh_file]") {
  // OpenMesh's readers are shared singletons: reads on several threads (Python threads, batch
  // jobs) must take turns, or its per-read state is torn and the heap corrupted.
  std::vector<std::string> paths;
  std::vector<size_t> vertexCounts;
  for (int k = 0; k < 4; ++k) {
    std::ostringstream obj;
    const int n = 200 + 50 * k;
    for (int i = 0; i < n; ++i) obj << "v " << i << " 0 " << k << "\nvt 0.5 0.5\n";
    for (int i = 1; i + 2 <= n; ++i) obj << "f " << i << "/1 " << i + 1 << "/2 " << i + 2 << "/3\n";
    std::ostringstream name;
    name << "t" << k << ".obj";
    paths.push_back(write(name.str(), obj.str()));
    vertexCounts.push_back(size_t(n));
  }
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 25; ++round) {
        const size_t k = size_t(t + round) % paths.size();
        MeshFileContent m;
        std::string error;
        if (!readMeshFile(paths[k], m, error) || m.vertices.size() != vertexCounts[k] ||
            m.polygonCount() != vertexCounts[k] - 2 || m.vertices.back()[2] != double(k))
          ++wrong;
      }
    });
  for (auto& th : threads) th.join();
  CHECK(wrong == 0);
}
