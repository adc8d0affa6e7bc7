// Texture coordinates from file to output mesh: read per corner from OBJ and PLY, kept by
// asset loading (seams split vertices, normalisation leaves them alone), carried through
// assembly unchanged while positions move.
#include "runtime/assemble.h"
#include "runtime/assets.h"
#include "runtime/io/read_mesh_file.h"
#include "scratch_files.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>

using namespace fgsg::rt;
namespace fs = std::filesystem;

namespace {

using UV = std::array<double, 2>;

std::string write(const std::string& name, const std::string& bytes) {
  static int n = 0;
  const fs::path dir = fgsg::test::scratchDir("texture_coordinates", std::to_string(n++));
  std::ofstream(dir / name, std::ios::binary) << bytes;
  return (dir / name).string();
}

io::MeshFileContent read(const std::string& name, const std::string& bytes) {
  io::MeshFileContent m;
  std::string error;
  const bool ok = io::readMeshFile(write(name, bytes), m, error);
  INFO(error);
  REQUIRE(ok);
  return m;
}

std::string readError(const std::string& name, const std::string& bytes) {
  io::MeshFileContent m;
  std::string error;
  CHECK_FALSE(io::readMeshFile(write(name, bytes), m, error));
  CHECK(m.cornerUV.empty());
  return error;
}

// Loads a mesh file as an asset, as I("name") would.
Mesh loadAsset(const std::string& name, const std::string& bytes) {
  const std::string path = write(name, bytes);
  AssetLibrary library;
  std::string error;
  const int index = library.resolve(path, error);
  INFO(error);
  REQUIRE(index >= 0);
  return library.mesh(index);
}

std::array<float, 3> position(const Mesh& m, size_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}
std::array<float, 2> texcoord(const Mesh& m, size_t v) {
  return {m.texcoords[2 * v], m.texcoords[2 * v + 1]};
}

// A 4 x 2 plate of two quads, the right one textured with its own copy of the left one's
// range: the shared edge x = 2 has u = 1 on the left and u = 0 on the right (a seam).
const char* const kSeamPlateObj =
    "v 0 0 0\nv 2 0 0\nv 4 0 0\nv 0 2 0\nv 2 2 0\nv 4 2 0\n"
    "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
    "f 1/1 2/2 5/4 4/3\nf 2/1 3/2 6/4 5/3\n";

}  // namespace

TEST_CASE("OBJ texture coordinates are read per face corner", "[texcoords]") {
  const auto m = read("seam.obj", kSeamPlateObj);
  REQUIRE(m.corners.size() == 8);
  REQUIRE(m.cornerUV.size() == 8);
  // Vertex 2 (index 1) is corner 1 of the left quad and corner 0 of the right one.
  CHECK(m.corners[1] == 1);
  CHECK(m.cornerUV[1] == UV{1, 0});
  CHECK(m.corners[4] == 1);
  CHECK(m.cornerUV[4] == UV{0, 0});
  CHECK(m.cornerUV[6] == UV{1, 1});
  // v/vt/vn and negative indices count as in the file.
  const auto n = read("vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.5\nvt 0.75 0.5\nvt 0.25 1\nvn 0 0 1\n"
                                "f 1/-3/1 2/-2/1 3/-1/1\n");
  CHECK(n.cornerUV == std::vector<UV>{{0.25, 0.5}, {0.75, 0.5}, {0.25, 1}});
}

TEST_CASE("OBJ without texture coordinates for every face has none", "[texcoords]") {
  CHECK(read("none.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").cornerUV.empty());
  const auto partial = read("partial.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                           "f 1/1 2/2 3/3\nf 2 4 3\n");
  CHECK(partial.polygonCount() == 2);
  CHECK(partial.cornerUV.empty());
  const auto later = read("later.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                       "f 2 4 3\nf 1/1 2/2 3/3\n");
  CHECK(later.cornerUV.empty());
}

TEST_CASE("PLY texture coordinates are read per vertex", "[texcoords]") {
  const auto m = read("uv.ply",
                      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                      "property float z\nproperty float u\nproperty float v\nelement face 2\n"
                      "property list uchar int vertex_indices\nend_header\n"
                      "0 0 0 0 0\n1 0 0 0.5 0\n1 1 0 0.5 0.25\n0 1 0 0 0.25\n3 0 1 2\n3 0 2 3\n");
  REQUIRE(m.cornerUV.size() == 6);
  CHECK(m.cornerUV == std::vector<UV>{{0, 0}, {0.5, 0}, {0.5, 0.25}, {0, 0}, {0.5, 0.25}, {0, 0.25}});
  // Some writers call them s t.
  const auto st = read("st.ply",
                       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                       "property float z\nproperty float s\nproperty float t\nelement face 1\n"
                       "property list uchar int vertex_indices\nend_header\n"
                       "0 0 0 0 0.5\n1 0 0 1 0.5\n0 1 0 0 1\n3 0 1 2\n");
  CHECK(st.cornerUV == std::vector<UV>{{0, 0.5}, {1, 0.5}, {0, 1}});
  CHECK(read("plain.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                          "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
            .cornerUV.empty());
}

TEST_CASE("texture coordinates that are not finite are errors", "[texcoords]") {
  CHECK_THAT(readError("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt nan 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n"),
             Catch::Contains("nan.obj:4: texture coordinate 'nan' is not a finite number"));
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty float u\nproperty float v\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float v[15] = {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, INFINITY, 1};
  ply.append(reinterpret_cast<const char*>(v), sizeof v);
  const unsigned char three = 3;
  const int32_t f[3] = {0, 1, 2};
  ply.append(reinterpret_cast<const char*>(&three), 1);
  ply.append(reinterpret_cast<const char*>(f), sizeof f);
  CHECK_THAT(readError("inf.ply", ply),
             Catch::Contains("vertex 2 has a texture coordinate that is not a finite number"));
}

TEST_CASE("loaded assets keep their texture coordinates, split at seams", "[texcoords][assets]") {
  const Mesh plate = loadAsset("seam.obj", kSeamPlateObj);
  CHECK(plate.triangleCount() == 4);
  // Flat, so normals alone would share the edge's two vertices; the seam splits them.
  CHECK(plate.vertexCount() == 8);
  REQUIRE(plate.hasTexcoords());
  for (size_t v = 0; v < plate.vertexCount(); ++v) {
    INFO("vertex " << v);
    // The plate was stretched onto the unit square; the texture coordinates were not.
    const auto p = position(plate, v);
    const auto t = texcoord(plate, v);
    const float x = p[0], localX = x < 0.5f || (x == 0.5f && t[0] == 1.0f) ? 2 * x : 2 * x - 1;
    CHECK(t[0] == localX);
    CHECK(t[1] == p[1]);
  }
  const Mesh untextured = loadAsset("plain.obj",
                                    "v 0 0 0\nv 2 0 0\nv 4 0 0\nv 0 2 0\nv 2 2 0\nv 4 2 0\n"
                                    "f 1 2 5 4\nf 2 3 6 5\n");
  CHECK(untextured.vertexCount() == 6);
  CHECK(untextured.texcoords.empty());
}

TEST_CASE("texture coordinates follow their corners through fans and split-off faces",
          "[texcoords][assets]") {
  // Three triangles on the edge 1-2: the third runs along it like the first, so the
  // importer splits it off onto copies of its vertices. Each corner's coordinate is a
  // function of its position (u = x, v = y + z), whatever path the corner took.
  const Mesh m = loadAsset("fin.obj",
                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0.5 0.5 0\n"
                           "vt 0 0\nvt 1 0\nvt 0 1\nvt 0 -1\nvt 0 1\nvt 0.5 0.5\n"
                           "f 1/1 2/2 6/6 3/3\nf 2/2 1/1 4/4\nf 1/1 2/2 5/5\n");
  CHECK(m.triangleCount() == 4);
  REQUIRE(m.hasTexcoords());
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    INFO("vertex " << v);
    // The box was x [0,1], y [-1,1], z [0,1]: undo the stretch of y.
    const auto p = position(m, v);
    const auto t = texcoord(m, v);
    CHECK(t[0] == Approx(p[0]));
    CHECK(t[1] == Approx(2 * p[1] - 1 + p[2]));
  }
}

TEST_CASE("PLY assets keep their per-vertex texture coordinates", "[texcoords][assets]") {
  const Mesh m = loadAsset("uv.ply",
                           "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                           "property float z\nproperty float u\nproperty float v\nelement face 1\n"
                           "property list uchar int vertex_indices\nend_header\n"
                           "0 0 0 0.5 0.5\n3 0 0 0.75 0.5\n3 3 0 0.75 0.75\n0 3 0 0.5 0.75\n4 0 1 2 3\n");
  REQUIRE(m.hasTexcoords());
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    CHECK(texcoord(m, v)[0] == 0.5f + 0.25f * position(m, v)[0]);
    CHECK(texcoord(m, v)[1] == 0.5f + 0.25f * position(m, v)[1]);
  }
}

namespace {

struct Scene {
  InstanceList list;
  AssetLibrary library;
  std::vector<int> meshOf;

  void add(const std::string& asset, const Eigen::Matrix4d& transform) {
    uint32_t index = 0;
    while (index < list.assets.size() && list.assets[index] != asset) ++index;
    if (index == list.assets.size()) list.assets.push_back(asset);
    Instance inst;
    inst.asset = index;
    Eigen::Map<Eigen::Matrix4d>(inst.transform.data()) = transform;  // column-major
    list.instances.push_back(inst);
  }
  Mesh assemble() {
    std::string error;
    REQUIRE(resolveAssets(list, library, meshOf, error));
    return assembleInstances(list, library, meshOf);
  }
};

Eigen::Matrix4d placement(double angle, Eigen::Vector3d scale, Eigen::Vector3d move) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
                        scale.asDiagonal();
  m.block<3, 1>(0, 3) = move;
  return m;
}

}  // namespace

TEST_CASE("assembly moves positions and keeps texture coordinates", "[texcoords][assemble]") {
  Scene scene;
  const Eigen::Matrix4d a = placement(0.7, {2, 0.5, 0.5}, {1, 2, 3});
  const Eigen::Matrix4d mirror = placement(-1.2, {-1, 3, 1}, {-4, 0, 1});
  scene.add("bark", a);
  scene.add("leaf", mirror);
  scene.add("bark", mirror);
  const Mesh out = scene.assemble();
  Mesh bark, leaf;
  REQUIRE(makeBuiltinPrimitive("bark", bark));
  REQUIRE(makeBuiltinPrimitive("leaf", leaf));
  REQUIRE(out.vertexCount() == 2 * bark.vertexCount() + leaf.vertexCount());
  REQUIRE(out.hasTexcoords());
  size_t at = 0;
  for (const auto& [asset, transform] : {std::pair{&bark, a}, {&leaf, mirror}, {&bark, mirror}}) {
    for (size_t v = 0; v < asset->vertexCount(); ++v, ++at) {
      INFO("output vertex " << at);
      CHECK(texcoord(out, at) == texcoord(*asset, v));
      const Eigen::Vector3d p(asset->positions[3 * v], asset->positions[3 * v + 1],
                              asset->positions[3 * v + 2]);
      const Eigen::Vector3d q = transform.block<3, 3>(0, 0) * p + transform.block<3, 1>(0, 3);
      for (int d = 0; d < 3; ++d) CHECK(out.positions[3 * at + d] == Approx(q[d]).margin(1e-6));
    }
  }
}

TEST_CASE("assets without texture coordinates get (0, 0) beside ones with them", "[texcoords][assemble]") {
  Scene mixed;
  mixed.add("cube", placement(0, {1, 1, 1}, {0, 0, 0}));
  mixed.add("leaf", placement(0, {1, 1, 1}, {2, 0, 0}));
  const Mesh out = mixed.assemble();
  REQUIRE(out.vertexCount() == 24 + 4);
  REQUIRE(out.hasTexcoords());
  for (size_t v = 0; v < 24; ++v) CHECK(texcoord(out, v) == std::array<float, 2>{0, 0});
  for (size_t v = 24; v < 28; ++v)  // the leaf: u = x, v = y in its own box
    CHECK(texcoord(out, v) == std::array<float, 2>{out.positions[3 * v] - 2, out.positions[3 * v + 1]});

  Scene plain;
  plain.add("cube", placement(0.3, {1, 2, 1}, {0, 0, 0}));
  plain.add("cylinder", placement(0, {1, 1, 1}, {2, 0, 0}));
  CHECK(plain.assemble().texcoords.empty());
}

TEST_CASE("an instance flattened away leaves no texture coordinates behind", "[texcoords][assemble]") {
  Scene scene;
  scene.add("leaf", placement(0, {0, 1, 1}, {0, 0, 0}));  // zero width: both triangles vanish
  scene.add("bark", placement(0, {1, 1, 1}, {0, 0, 0}));
  const Mesh out = scene.assemble();
  CHECK(out.vertexCount() == 250);
  CHECK(out.texcoords.size() == 2 * 250);
}
