// Built-in primitives and mesh-file assets: unit-box normalisation, closedness,
// orientation, triangle counts, and the loader's error messages.
#include "runtime/assets.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

using namespace fgsg::rt;
namespace fs = std::filesystem;

namespace {

fs::path scratchDir(const std::string& name) {
  // Under the build tree, one folder per test case: cases may run as parallel processes.
  const fs::path dir = fs::path(FGSG_BINARY_DIR) / "test-scratch" / "assets" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeText(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::array<double, 3> corner(const Mesh& m, uint32_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

std::array<double, 3> faceNormal(const Mesh& m, size_t t) {  // unnormalised, from the winding
  const auto a = corner(m, m.indices[3 * t]), b = corner(m, m.indices[3 * t + 1]),
             c = corner(m, m.indices[3 * t + 2]);
  const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
}

// Signed volume by the divergence theorem: positive when the triangles face outwards.
double signedVolume(const Mesh& m) {
  double vol = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const auto a = corner(m, m.indices[3 * t]);
    const auto n = faceNormal(m, t);
    vol += (a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / 6.0;
  }
  return vol;
}

// Every undirected edge, with vertices welded by exact position (sharp primitives split
// their vertices per face), is used by exactly two triangles, once in each direction.
bool watertight(const Mesh& m) {
  std::map<std::array<float, 3>, uint32_t> weld;
  std::vector<uint32_t> id(m.vertexCount());
  for (uint32_t v = 0; v < m.vertexCount(); ++v) {
    const std::array<float, 3> p{m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
    id[v] = weld.emplace(p, uint32_t(weld.size())).first->second;
  }
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) ++directed[{id[m.indices[3 * t + k]], id[m.indices[3 * t + (k + 1) % 3]]}];
  for (const auto& [e, n] : directed) {
    if (n != 1) return false;
    auto back = directed.find({e.second, e.first});
    if (back == directed.end() || back->second != 1) return false;
  }
  return true;
}

// Vertex normals are unit length and on the same side as the winding's face normal.
void checkNormals(const Mesh& m) {
  REQUIRE(m.normals.size() == m.positions.size());
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const double len = std::hypot(m.normals[3 * v], m.normals[3 * v + 1], m.normals[3 * v + 2]);
    REQUIRE(len == Approx(1.0).margin(1e-6));
  }
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const auto n = faceNormal(m, t);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = m.indices[3 * t + k];
      const double dot = n[0] * m.normals[3 * v] + n[1] * m.normals[3 * v + 1] + n[2] * m.normals[3 * v + 2];
      REQUIRE(dot > 0);
    }
  }
}

}  // namespace

TEST_CASE("built-in primitives are listed in a stable order", "[assets]") {
  CHECK(builtinPrimitiveNames() ==
        std::vector<std::string>{"cube", "cylinder", "sphere", "torus", "ico", "quad", "disc", "bark",
                                 "leaf", "line", "none"});
  Mesh m;
  CHECK(makeBuiltinPrimitive("none", m));  // I("none") places nothing
  CHECK(m.triangleCount() == 0);
  CHECK_FALSE(makeBuiltinPrimitive("Torus", m));  // names are exact
  CHECK_FALSE(makeBuiltinPrimitive("box", m));
}

TEST_CASE("closed primitives fill the unit cube, are watertight and face outwards", "[assets]") {
  const std::map<std::string, size_t> triangles = {
      {"cube", 12}, {"cylinder", 128}, {"sphere", 960}, {"torus", 1536}, {"ico", 80}};
  for (const auto& [name, count] : triangles) {
    INFO(name);
    Mesh m;
    REQUIRE(makeBuiltinPrimitive(name, m));
    CHECK(m.triangleCount() == count);
    CHECK(m.boundsMin() == std::array<float, 3>{0, 0, 0});
    CHECK(m.boundsMax() == std::array<float, 3>{1, 1, 1});
    CHECK(m.colors.empty());
    CHECK(m.texcoords.empty());  // only the marching terminals have them
    CHECK(watertight(m));
    CHECK(signedVolume(m) > 0);
    checkNormals(m);
  }
}

TEST_CASE("primitive volumes match their shapes in the unit box", "[assets]") {
  const auto volume = [](const char* name) {
    Mesh m;
    makeBuiltinPrimitive(name, m);
    return signedVolume(m);
  };
  CHECK(volume("cube") == Approx(1.0).epsilon(1e-12));
  // Tessellated round shapes lose a little volume against the smooth ones.
  const double pi = 3.14159265358979323846;
  CHECK(volume("sphere") == Approx(pi / 6).epsilon(0.03));
  CHECK(volume("sphere") < pi / 6);
  CHECK(volume("cylinder") == Approx(pi / 4).epsilon(0.01));
  // Torus R = 3, r = 1: 2 pi^2 R r^2 inside an 8 x 8 x 2 box.
  CHECK(volume("torus") == Approx(2 * pi * pi * 3 / 128).epsilon(0.03));
  CHECK(volume("ico") == Approx(pi / 6).epsilon(0.15));
}

TEST_CASE("the torus lies in the XY plane and its tube is an eighth of its width", "[assets]") {
  Mesh m;
  REQUIRE(makeBuiltinPrimitive("torus", m));
  // The hole: no vertex within the inner radius (R - r) / (2 (R + r)) = 1/4 of the centre
  // in XY; the vertices at the inner equator sit exactly there.
  double minRadius = 1;
  for (size_t v = 0; v < m.vertexCount(); ++v)
    minRadius = std::min(minRadius, std::hypot(m.positions[3 * v] - 0.5, m.positions[3 * v + 1] - 0.5));
  CHECK(minRadius == Approx(0.25).margin(1e-6));
}

TEST_CASE("flat primitives lie in z = 0 facing +Z", "[assets]") {
  for (const auto& [name, count] : std::map<std::string, size_t>{{"quad", 2}, {"disc", 32}}) {
    INFO(name);
    Mesh m;
    REQUIRE(makeBuiltinPrimitive(name, m));
    CHECK(m.triangleCount() == count);
    CHECK(m.boundsMin() == std::array<float, 3>{0, 0, 0});
    CHECK(m.boundsMax() == std::array<float, 3>{1, 1, 0});
    for (size_t v = 0; v < m.vertexCount(); ++v) {
      CHECK(m.positions[3 * v + 2] == 0.0f);
      CHECK(m.normals[3 * v + 2] == 1.0f);
    }
    CHECK(m.texcoords.empty());
    checkNormals(m);
  }
}

namespace {

// Twice the signed area of triangle t in texture space: positive when the texture is not
// mirrored on the triangle's front side (its corners run counter-clockwise in UV too).
double uvArea2(const Mesh& m, size_t t) {
  const auto uv = [&](int k) {
    const uint32_t v = m.indices[3 * t + k];
    return std::array<double, 2>{m.texcoords[2 * v], m.texcoords[2 * v + 1]};
  };
  const auto a = uv(0), b = uv(1), c = uv(2);
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

}  // namespace

TEST_CASE("bark is a 24 x 9 tube along X of radius 0.5 with smooth normals and UVs", "[assets]") {
  Mesh m;
  REQUIRE(makeBuiltinPrimitive("bark", m));
  CHECK(m.triangleCount() == 432);  // 216 quads, the paper's bark cylinder
  CHECK(m.vertexCount() == 250);    // 25 per ring (a seam column) x 10 rings
  CHECK(m.boundsMin() == std::array<float, 3>{0, 0, 0});
  CHECK(m.boundsMax() == std::array<float, 3>{1, 1, 1});
  REQUIRE(m.texcoords.size() == 2 * m.vertexCount());
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    INFO("vertex " << v);
    const double y = m.positions[3 * v + 1] - 0.5, z = m.positions[3 * v + 2] - 0.5;
    CHECK(std::hypot(y, z) == Approx(0.5).margin(1e-6));
    // Smooth: the normal is the radial direction, with no X part.
    CHECK(m.normals[3 * v] == 0.0f);
    CHECK(m.normals[3 * v + 1] == Approx(2 * y).margin(1e-6));
    CHECK(m.normals[3 * v + 2] == Approx(2 * z).margin(1e-6));
    const float u = m.texcoords[2 * v], tv = m.texcoords[2 * v + 1];
    CHECK(u >= 0.0f);
    CHECK(u <= 1.0f);
    CHECK(tv == m.positions[3 * v]);  // v runs along X
    // u runs around X from +Y towards +Z.
    const double angle = std::atan2(z, y), around = angle < -1e-9 ? angle + 2 * M_PI : angle;
    if (u < 1.0f) CHECK(u == Approx(around / (2 * M_PI)).margin(1e-6));
  }
  checkNormals(m);
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    INFO("triangle " << t);
    CHECK(uvArea2(m, t) > 0);  // not mirrored, and no triangle wraps across the seam
    CHECK(uvArea2(m, t) == Approx(1.0 / (24 * 9)));
  }
}

TEST_CASE("tubeN is an open tube along Y with N sides filling the unit box, normals pointing out", "[assets]") {
  Mesh m;
  REQUIRE(makeBuiltinPrimitive("tube8", m));
  CHECK(m.vertexCount() == 16);
  CHECK(m.triangleCount() == 16);
  CHECK(m.boundsMin() == std::array<float, 3>{0, 0, 0});
  CHECK(m.boundsMax() == std::array<float, 3>{1, 1, 1});
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    // Radial (an octagon's box is square, so the stretch is uniform): no Y part, along
    // the vertex's direction from the axis (x = z = 0.5), outwards.
    const double dx = m.positions[3 * v] - 0.5, dz = m.positions[3 * v + 2] - 0.5;
    CHECK(m.normals[3 * v + 1] == Approx(0).margin(1e-6));
    CHECK(m.normals[3 * v] * dz - m.normals[3 * v + 2] * dx == Approx(0).margin(1e-6));
    CHECK(m.normals[3 * v] * dx + m.normals[3 * v + 2] * dz > 0);
  }
  REQUIRE(makeBuiltinPrimitive("tube6", m));
  CHECK(m.triangleCount() == 12);
  CHECK(m.boundsMax() == std::array<float, 3>{1, 1, 1});
  REQUIRE(makeBuiltinPrimitive("tube64", m));
  CHECK(m.triangleCount() == 128);
  REQUIRE(makeBuiltinPrimitive("tube3", m));
  CHECK(m.triangleCount() == 6);
  for (const char* name : {"tube", "tube2", "tube65", "tube06", "tube6x", "tube100"}) {
    INFO(name);
    CHECK_FALSE(makeBuiltinPrimitive(name, m));
  }
}

TEST_CASE("leaf is the XY unit square facing +Z with UVs covering it", "[assets]") {
  Mesh m;
  REQUIRE(makeBuiltinPrimitive("leaf", m));
  CHECK(m.triangleCount() == 2);
  CHECK(m.boundsMin() == std::array<float, 3>{0, 0, 0});
  CHECK(m.boundsMax() == std::array<float, 3>{1, 1, 0});
  REQUIRE(m.texcoords.size() == 2 * m.vertexCount());
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    CHECK(m.texcoords[2 * v] == m.positions[3 * v]);          // u = x
    CHECK(m.texcoords[2 * v + 1] == m.positions[3 * v + 1]);  // v = y
  }
  CHECK(uvArea2(m, 0) + uvArea2(m, 1) == 2.0);  // the whole square, upright seen from +Z
  checkNormals(m);
}

TEST_CASE("computeNormals gives area-weighted unit normals", "[assets]") {
  Mesh m;
  REQUIRE(makeBuiltinPrimitive("quad", m));
  m.normals.clear();
  m.computeNormals();
  for (size_t v = 0; v < m.vertexCount(); ++v)
    CHECK(std::array<float, 3>{m.normals[3 * v], m.normals[3 * v + 1], m.normals[3 * v + 2]} ==
          std::array<float, 3>{0, 0, 1});
}

TEST_CASE("the asset library resolves built-ins once", "[assets]") {
  AssetLibrary lib;
  std::string error;
  const int torus = lib.resolve("torus", error);
  REQUIRE(torus >= 0);
  CHECK(lib.resolve("torus", error) == torus);
  CHECK(lib.resolve("cube", error) != torus);
  CHECK(lib.mesh(torus).triangleCount() == 1536);
}

TEST_CASE("mesh files load triangulated into the unit box with sharp creases", "[assets]") {
  const fs::path dir = scratchDir("load");
  // A 2 x 4 x 6 box made of quads, away from the origin.
  writeText(dir / "box.obj",
            "v 1 1 1\nv 3 1 1\nv 3 5 1\nv 1 5 1\nv 1 1 7\nv 3 1 7\nv 3 5 7\nv 1 5 7\n"
            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  AssetLibrary lib;
  lib.addSearchDir((dir / "missing").string());
  lib.addSearchDir(dir.string());
  std::string error;
  const int box = lib.resolve("box.obj", error);
  REQUIRE(box >= 0);
  const Mesh& m = lib.mesh(box);
  CHECK(m.triangleCount() == 12);
  CHECK(m.vertexCount() == 24);  // split at the 90 degree creases
  CHECK(m.boundsMin() == std::array<float, 3>{0, 0, 0});
  CHECK(m.boundsMax() == std::array<float, 3>{1, 1, 1});
  CHECK(watertight(m));
  CHECK(signedVolume(m) == Approx(1.0));
  checkNormals(m);
  for (float n : m.normals) CHECK((n == 0.0f || std::abs(n) == 1.0f));

  SECTION("absolute paths need no search directory") {
    AssetLibrary plain;
    CHECK(plain.resolve((dir / "box.obj").string(), error) >= 0);
  }
  SECTION("a planar mesh stays flat at z = 0") {
    writeText(dir / "plate.obj", "v 0 0 5\nv 4 0 5\nv 4 2 5\nv 0 2 5\nf 1 2 3 4\n");
    const int plate = lib.resolve("plate.obj", error);
    REQUIRE(plate >= 0);
    CHECK(lib.mesh(plate).boundsMin() == std::array<float, 3>{0, 0, 0});
    CHECK(lib.mesh(plate).boundsMax() == std::array<float, 3>{1, 1, 0});
    CHECK(lib.mesh(plate).triangleCount() == 2);
  }
  SECTION("OFF, PLY and STL load too") {
    writeText(dir / "tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 1\n3 0 1 2\n");
    writeText(dir / "tri.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
              "0 0 0\n1 0 0\n0 1 1\n3 0 1 2\n");
    writeText(dir / "tri.stl",
              "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 1\n"
              "endloop\nendfacet\nendsolid t\n");
    for (const char* name : {"tri.off", "tri.ply", "tri.stl"}) {
      INFO(name);
      const int i = lib.resolve(name, error);
      INFO(error);
      REQUIRE(i >= 0);
      CHECK(lib.mesh(i).triangleCount() == 1);
      CHECK(lib.mesh(i).boundsMax() == std::array<float, 3>{1, 1, 1});
    }
  }
}

TEST_CASE("asset errors say what is wrong", "[assets]") {
  const fs::path dir = scratchDir("errors");
  AssetLibrary lib;
  lib.addSearchDir(dir.string());
  std::string error;

  SECTION("not found lists the directories searched and the built-ins") {
    CHECK(lib.resolve("wall.obj", error) == -1);
    CHECK_THAT(error, Catch::Contains("'wall.obj' not found"));
    CHECK_THAT(error, Catch::Contains(dir.string()));
    CHECK_THAT(error, Catch::Contains("cube, cylinder, sphere, torus, ico, quad, disc"));
  }
  SECTION("unsupported format") {
    writeText(dir / "wall.xyz", "1 2 3\n");
    CHECK(lib.resolve("wall.xyz", error) == -1);
    CHECK_THAT(error, Catch::Contains("unsupported format '.xyz'"));
    CHECK_THAT(error, Catch::Contains(".obj .ply .off .stl"));
  }
  SECTION("unreadable file") {
    writeText(dir / "broken.ply", "this is not a ply file\n");
    CHECK(lib.resolve("broken.ply", error) == -1);
    CHECK_THAT(error, Catch::Contains("cannot read asset file"));
  }
  SECTION("no faces") {
    writeText(dir / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    CHECK(lib.resolve("points.obj", error) == -1);
    CHECK_THAT(error, Catch::Contains("contains no faces"));
  }
  SECTION("NaN coordinates") {
    // Binary PLY: text formats cannot spell NaN portably.
    std::string ply =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const float v[9] = {0, 0, 0, 1, 0, 0, 0, NAN, 0};
    ply.append(reinterpret_cast<const char*>(v), sizeof v);
    const unsigned char n = 3;
    const int32_t f[3] = {0, 1, 2};
    ply.append(reinterpret_cast<const char*>(&n), 1);
    ply.append(reinterpret_cast<const char*>(f), sizeof f);
    writeText(dir / "nan.ply", ply);
    CHECK(lib.resolve("nan.ply", error) == -1);
    CHECK_THAT(error, Catch::Contains("NaN"));
  }
}
