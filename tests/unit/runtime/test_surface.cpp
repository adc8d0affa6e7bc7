// Surfaces: the procedural ones (validity, topology, area, orientation, triangle shape),
// loading real meshes from tests/data/meshes (scripts/fetch-test-meshes.sh), the clear
// error for each kind of broken input, what repair fixes and what it refuses, and
// closest-point queries against brute force.
#include "runtime/surface/load_surface.h"
#include "runtime/surface/locate.h"
#include "runtime/surface/procedural.h"

#include "scratch_files.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <thread>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

using namespace fgsg::rt;
using namespace fgsg::rt::surface;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

fs::path scratchDir(const std::string& name) { return fgsg::test::scratchDir("surface", name); }

void writeText(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// Boundary half-edges, and from them the edge count of a manifold mesh.
size_t boundaryEdges(const SurfaceMesh& m) {
  size_t n = 0;
  for (const auto& t : m.neighbours)
    for (int g : t) n += g < 0;
  return n;
}

long euler(const SurfaceMesh& m) {
  const size_t edges = (3 * m.faceCount() + boundaryEdges(m)) / 2;
  return long(m.vertexCount()) - long(edges) + long(m.faceCount());
}

double area(const SurfaceMesh& m) {
  double a = 0;
  for (double f : m.faceAreas) a += f;
  return a;
}

// Divergence theorem: positive when a closed surface's faces point outwards.
double signedVolume(const SurfaceMesh& m) {
  double v = 0;
  for (const auto& t : m.faces)
    v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6;
  return v;
}

double minAngleDegrees(const SurfaceMesh& m) {
  double smallest = 180;
  for (const auto& t : m.faces)
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = m.vertices[t[(k + 1) % 3]] - m.vertices[t[k]];
      const Vec3 b = m.vertices[t[(k + 2) % 3]] - m.vertices[t[k]];
      smallest = std::min(smallest, std::acos(a.normalized().dot(b.normalized())) * 180 / kPi);
    }
  return smallest;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

// Across every edge with a neighbour, the neighbour has this face across the same edge,
// traversed the other way.
void checkNeighboursPointBack(const SurfaceMesh& m) {
  size_t bad = 0;
  for (size_t f = 0; f < m.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = m.neighbours[f][k];
      if (g < 0) continue;
      const int a = m.faces[f][k], b = m.faces[f][(k + 1) % 3];
      const int j = m.cornerOf(g, b);
      if (j < 0 || m.neighbours[g][j] != int(f) || m.faces[g][(j + 1) % 3] != a) ++bad;
    }
  CHECK(bad == 0);
}

// facesAround(v) lists every face at v once, each the neighbour of the one before across
// the edge leaving v; a full ring for an interior vertex, boundary to boundary otherwise.
void checkRings(const SurfaceMesh& m) {
  std::vector<int> count(m.vertexCount(), 0);
  for (const auto& t : m.faces)
    for (int v : t) ++count[v];
  size_t bad = 0;
  for (int v = 0; v < int(m.vertexCount()); ++v) {
    const auto ring = m.facesAround(v);
    if (int(ring.size()) != count[v]) {
      ++bad;
      continue;
    }
    const int n = int(ring.size());
    for (int i = 0; i < n; ++i) {
      const int f = ring[i], k = m.cornerOf(f, v);
      const int next = m.neighbours[f][k];
      if (i + 1 < n ? next != ring[i + 1] : (m.boundaryVertex[v] ? next != -1 : next != ring[0]))
        ++bad;
    }
    if (m.boundaryVertex[v] && n > 0) {
      const int f = ring[0], k = m.cornerOf(f, v);
      if (m.neighbours[f][(k + 2) % 3] != -1) ++bad;  // starts at the boundary
    }
  }
  CHECK(bad == 0);
}

// Checks everything a sound surface promises; `closed` and `chi` as expected.
void checkSound(const SurfaceMesh& m, bool closed, long chi) {
  std::vector<std::string> problems;
  INFO(joined(problems));
  REQUIRE(validateSurface(m, problems));
  CHECK(problems.empty());
  REQUIRE(m.neighbours.size() == m.faceCount());
  CHECK(euler(m) == chi);
  CHECK((boundaryEdges(m) == 0) == closed);
  checkNeighboursPointBack(m);
  checkRings(m);
}

fs::path meshDir() {
  const fs::path dir = fs::path(FGSG_SOURCE_DIR) / "tests" / "data" / "meshes";
  if (!fs::is_directory(dir))
    FAIL(
        "tests/data/meshes is missing: run scripts/fetch-test-meshes.sh (see "
        "tests/data/README.md)");
  return dir;
}

fs::path meshFile(const std::string& name) {
  const fs::path p = meshDir() / name;
  if (!fs::exists(p))
    FAIL("tests/data/meshes/" + name + " is missing: run scripts/fetch-test-meshes.sh");
  return p;
}

// The loader's error for `text` written to a scratch file `name`.
std::string loadError(const std::string& dir, const std::string& name, const std::string& text,
                      bool repair = false, SurfaceRepairReport* report = nullptr,
                      SurfaceMesh* loaded = nullptr) {
  const fs::path p = scratchDir(dir) / name;
  writeText(p, text);
  SurfaceMesh m;
  std::string error;
  SurfaceLoadOptions options;
  options.repair = repair;
  const bool ok = loadSurface(p.string(), m, error, options, report);
  if (loaded) *loaded = m;
  return ok ? std::string() : error;
}

// A binary little-endian PLY file: floats reach the loader exactly as written, NaN included.
std::string binaryPly(const std::vector<Vec3>& vertices,
                      const std::vector<std::array<int, 3>>& faces) {
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices.size()) +
      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
      std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : vertices) {
    const float xyz[3] = {float(p.x()), float(p.y()), float(p.z())};
    s.append(reinterpret_cast<const char*>(xyz), 12);
  }
  for (const auto& t : faces) {
    s.push_back(char(3));
    const int32_t corners[3] = {t[0], t[1], t[2]};
    s.append(reinterpret_cast<const char*>(corners), 12);
  }
  return s;
}

// A 3 x 3 vertex grid in the XY plane: 4 squares, 8 triangles, all facing +Z.
const char* const kGridOff =
    "OFF\n9 8 0\n"
    "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n"
    "3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 3 4 7\n3 3 7 6\n3 4 5 8\n3 4 8 7\n";

}  // namespace

// ---- procedural surfaces ----

TEST_CASE("procedural surfaces are sound, with the right topology", "[surface]") {
  SECTION("torus") {
    const SurfaceMesh m = torus(1.0, 0.4);
    checkSound(m, true, 0);
    CHECK(area(m) == Approx(4 * kPi * kPi * 1.0 * 0.4).epsilon(0.01));
    CHECK(signedVolume(m) > 0);
  }
  SECTION("sphere") {
    const SurfaceMesh m = sphere(2.0);
    checkSound(m, true, 2);
    CHECK(area(m) == Approx(4 * kPi * 4.0).epsilon(0.01));
    CHECK(signedVolume(m) == Approx(4.0 / 3 * kPi * 8).epsilon(0.02));
  }
  SECTION("genus 2") {
    const SurfaceMesh m = genus2();
    checkSound(m, true, -2);
    CHECK(signedVolume(m) > 0);
  }
  SECTION("three tori: closed, genus 7, on the tori and outside every tube") {
    const double R = 1.0, r = 0.3;
    const SurfaceMesh m = threeTori(R, r, 24);
    checkSound(m, true, -12);
    CHECK(signedVolume(m) > 0);
    // Distance from p to the tube of the torus about `axis` (negative: inside the tube).
    auto tube = [&](const Vec3& p, int axis) {
      const double along = p[axis];
      const double across = std::sqrt(std::max(0.0, p.squaredNorm() - along * along));
      return std::hypot(across - R, along) - r;
    };
    double worstOn = 0, deepestInside = 0;
    for (const Vec3& p : m.vertices) {
      const double d[3] = {tube(p, 2), tube(p, 0), tube(p, 1)};
      worstOn = std::max(worstOn, std::abs(std::min({d[0], d[1], d[2]})));
      deepestInside = std::min({deepestInside, d[0], d[1], d[2]});
    }
    // Remeshing moves vertices back onto the union of the polygonal tori, whose faces
    // sag from the smooth tubes by r (1 - cos(pi / 24)) across the tube and as much again
    // along it.
    CHECK(worstOn < 0.02 * r);
    CHECK(deepestInside > -0.02 * r);
    CHECK(minAngleDegrees(m) > 5);
    // Built again (elsewhere in memory, on another thread): the same mesh.
    SurfaceMesh again;
    std::thread([&] { again = threeTori(R, r, 24); }).join();
    CHECK(again.vertices == m.vertices);
    CHECK(again.faces == m.faces);
  }
  SECTION("plane: flat, centred, facing +Z") {
    const SurfaceMesh m = plane(3.0, 2.0);
    checkSound(m, false, 1);
    CHECK(area(m) == Approx(6.0));
    for (const Vec3& n : m.faceNormals) CHECK(n.z() == Approx(1.0));
    CHECK(m.boundsMin.isApprox(Vec3(-1.5, -1, 0)));
    CHECK(m.boundsMax.isApprox(Vec3(1.5, 1, 0)));
  }
  SECTION("cylinder: open, normals away from the axis") {
    const SurfaceMesh m = cylinder(0.5, 3.0);
    checkSound(m, false, 0);
    CHECK(area(m) == Approx(2 * kPi * 0.5 * 3.0).epsilon(0.01));
    for (size_t v = 0; v < m.vertexCount(); ++v) {
      const Vec3 radial(m.vertices[v].x(), m.vertices[v].y(), 0);
      CHECK(m.vertexNormals[v].dot(radial.normalized()) > 0.99);
    }
    CHECK(m.boundsMin.z() == Approx(-1.5));
    CHECK(m.boundsMax.z() == Approx(1.5));
  }
}

TEST_CASE("procedural surfaces have well-shaped triangles", "[surface]") {
  // Grids split into right triangles (45 degrees at best); a subdivided icosahedron is
  // near-equilateral; Catmull-Clark quads stay near-square.
  CHECK(minAngleDegrees(torus()) > 30);
  CHECK(minAngleDegrees(torus(3.0, 0.2)) > 30);
  CHECK(minAngleDegrees(sphere()) > 45);
  CHECK(minAngleDegrees(plane(5.0, 1.0)) > 40);
  CHECK(minAngleDegrees(cylinder(1.0, 0.3)) > 30);
  CHECK(minAngleDegrees(genus2()) > 20);
  CHECK(minAngleDegrees(genus2(2.0, 0.25)) > 20);
  CHECK(minAngleDegrees(genus2(1.0, 0.9, 2)) > 20);  // thin holes, thick bars
}

TEST_CASE("procedural surfaces: resolution and parameters", "[surface]") {
  // Area converges from below as the resolution grows.
  const double exact = 4 * kPi * kPi * 2.0 * 0.5;
  const double coarse = area(torus(2.0, 0.5, 12)), fine = area(torus(2.0, 0.5, 64));
  CHECK(coarse < fine);
  CHECK(fine < exact);
  CHECK(fine == Approx(exact).epsilon(0.001));
  CHECK(sphere(1.0, 0).faceCount() == 20);
  CHECK(sphere(1.0, 2).faceCount() == 320);
  checkSound(genus2(1.5, 0.3, 2), true, -2);
  checkSound(genus2(1.0, 0.4, 0), true, -2);  // the cage itself
  checkSound(torus(1.0, 0.9, 5), true, 0);
}

TEST_CASE("makeProceduralSurface: names, defaults and errors", "[surface]") {
  SurfaceMesh m;
  std::string error;
  CHECK(proceduralSurfaceNames() ==
        std::vector<std::string>{"torus", "sphere", "plane", "genus2", "cylinder", "tori3"});
  for (const auto& name : proceduralSurfaceNames()) {
    INFO(name);
    REQUIRE(makeProceduralSurface(name, {}, m, error));
    std::vector<std::string> problems;
    CHECK(validateSurface(m, problems));
    CHECK_FALSE(proceduralSurfaceSignature(name).empty());
  }
  CHECK(proceduralSurfaceSignature("torus") == "torus(R = 1, r = 0.4, segments = 32)");
  CHECK(proceduralSurfaceSignature("teapot").empty());

  // Missing trailing arguments take the defaults.
  REQUIRE(makeProceduralSurface("torus", {2.0}, m, error));
  CHECK(area(m) == Approx(4 * kPi * kPi * 2.0 * 0.4).epsilon(0.01));
  REQUIRE(makeProceduralSurface("sphere", {3.0, 1}, m, error));
  CHECK(m.faceCount() == 80);

  auto fails = [&](const std::string& name, const std::vector<double>& args) {
    const bool ok = makeProceduralSurface(name, args, m, error);
    CHECK(m.faceCount() == 0);
    return ok ? std::string("(built)") : error;
  };
  CHECK_THAT(fails("torus", {0.3, 0.5}), Catch::Contains("torus(R, r) needs R > r > 0"));
  CHECK_THAT(fails("torus", {1.0, -0.1}), Catch::Contains("needs R > r > 0"));
  CHECK_THAT(fails("genus2", {0.4, 0.4}), Catch::Contains("genus2(R, r) needs R > r > 0"));
  CHECK_THAT(fails("tori3", {1.0, 0.5}), Catch::Contains("tori3(R, r) needs R > 2r > 0"));
  CHECK_THAT(fails("tori3", {1.0, 0.3, 4}), Catch::Contains("between 8 and 256"));
  CHECK_THAT(fails("sphere", {0.0}), Catch::Contains("sphere(r) needs r > 0"));
  CHECK_THAT(fails("plane", {1.0, -2.0}), Catch::Contains("needs w > 0 and h > 0"));
  CHECK_THAT(fails("cylinder", {1.0, 0.0}), Catch::Contains("needs r > 0 and h > 0"));
  CHECK_THAT(fails("torus", {1.0, 0.4, 2.5}),
             Catch::Contains("segments must be a finite whole number"));
  CHECK_THAT(fails("torus", {1.0, 0.4, 2}), Catch::Contains("between 3 and"));
  CHECK_THAT(fails("sphere", {1.0, 12}), Catch::Contains("between 0 and 8"));
  CHECK_THAT(fails("sphere", {NAN}), Catch::Contains("must be a finite"));
  CHECK_THAT(fails("torus", {100.0, 0.001}), Catch::Contains("allowed"));
  CHECK_THAT(fails("sphere", {1, 2, 3}), Catch::Contains("takes at most 2 arguments, got 3"));
  const std::string unknown = fails("teapot", {});
  CHECK_THAT(unknown, Catch::Contains("unknown procedural surface 'teapot'"));
  CHECK_THAT(unknown, Catch::Contains("genus2(R = 1, r = 0.4, levels = 3)"));
}

// ---- validation of in-memory meshes ----

TEST_CASE("validateSurface on in-memory meshes", "[surface]") {
  std::vector<std::string> problems;
  SECTION("no faces") {
    SurfaceMesh m;
    CHECK_FALSE(validateSurface(m, problems));
    CHECK_THAT(joined(problems), Catch::Contains("the surface has no faces"));
  }
  SECTION("bad vertex index") {
    SurfaceMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.faces = {{0, 1, 7}};
    CHECK_FALSE(validateSurface(m, problems));
    CHECK_THAT(joined(problems),
               Catch::Contains("face 0 refers to vertex 7, but there are only 3"));
    CHECK_FALSE(repairSurface(m).any());  // nothing to renumber safely
  }
  SECTION("many problems: ten listed, the rest counted") {
    SurfaceMesh m = plane(1.0, 1.0, 2);
    for (int i = 0; i < 30; ++i) m.vertices.push_back(Vec3(5, 5, i));
    CHECK_FALSE(validateSurface(m, problems));
    REQUIRE(problems.size() == kMaxListedProblems + 1);
    CHECK(problems.back() == "and 20 more: 20 isolated vertices");
  }
  SECTION("kinds share the listed lines") {
    SurfaceMesh m = plane(1.0, 1.0, 2);
    for (int i = 0; i < 30; ++i) m.vertices.push_back(Vec3(5, 5, i));
    m.faces.push_back(m.faces[0]);  // one duplicate among 30 isolated vertices
    CHECK_FALSE(validateSurface(m, problems));
    CHECK_THAT(joined(problems), Catch::Contains("(duplicate face)"));
    CHECK(problems.back() == "and 21 more: 21 isolated vertices");
  }
  SECTION("a Moebius strip cannot be oriented, so repair leaves it") {
    SurfaceMesh m;
    const int n = 24;
    for (int i = 0; i < n; ++i) {
      const double u = 2 * kPi * i / n;
      for (double s : {-0.3, 0.3}) {
        const double d = 1 + s * std::cos(u / 2);
        m.vertices.push_back(Vec3(d * std::cos(u), d * std::sin(u), s * std::sin(u / 2)));
      }
    }
    for (int i = 0; i < n; ++i) {
      const int a = 2 * i, b = 2 * i + 1;
      // The last strip joins the first with a half twist.
      const int c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
      m.faces.push_back({a, c, d});
      m.faces.push_back({a, d, b});
    }
    CHECK_FALSE(validateSurface(m, problems));
    CHECK_THAT(joined(problems), Catch::Contains("(inconsistent orientation)"));
    const SurfaceRepairReport report = repairSurface(m);
    CHECK(report.flippedFaces == 0);
    problems.clear();
    CHECK_FALSE(validateSurface(m, problems));
  }
  SECTION("repair turns an inward-facing closed surface outwards") {
    SurfaceMesh m = sphere(1.0, 1);
    for (auto& t : m.faces) std::swap(t[1], t[2]);
    CHECK(validateSurface(m, problems));  // consistent, only inside out
    const SurfaceRepairReport report = repairSurface(m);
    CHECK(report.flippedFaces == m.faceCount());
    CHECK(report.summary() == "flipped 80 faces");
    m.buildTopology();
    CHECK(signedVolume(m) > 0);
  }
}

// ---- broken files: one clear error each ----

TEST_CASE("loading reports each kind of broken input clearly", "[surface]") {
  SECTION("missing file, unknown extension, empty file, unreadable file") {
    SurfaceMesh m;
    std::string error;
    const fs::path dir = scratchDir("unreadable");
    CHECK_FALSE(loadSurface((dir / "nothing.off").string(), m, error));
    CHECK_THAT(error, Catch::Contains("nothing.off: no such file"));
    CHECK_THAT(loadError("unreadable", "mesh.xyz", "whatever"),
               Catch::Contains("unknown surface format '.xyz' (supported: .obj .ply .off .stl .gltf .glb .fbx .dae)"));
    CHECK_THAT(loadError("unreadable", "mesh", kGridOff),
               Catch::Contains("unknown surface format"));
    CHECK_THAT(loadError("unreadable", "empty.obj", ""),
               Catch::Contains("empty.obj: the file is empty"));
    CHECK_THAT(loadError("unreadable", "junk.off", "this is not a mesh\n"),
               Catch::Contains("cannot read the file"));
    CHECK_THAT(loadError("unreadable", "nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"),
               Catch::Contains("the surface has no faces"));
  }
  SECTION("NaN and infinite coordinates") {
    // Text: found before OpenMesh (which would read garbage), with the line.
    const std::string obj = loadError("nan", "nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
    CHECK_THAT(obj, Catch::Contains("nan.obj:3: vertex coordinate 'nan' is not a finite number"));
    CHECK_THAT(loadError("nan", "inf.off", "OFF\n3 1 0\n0 0 0\n1 0 -inf\n0 1 0\n3 0 1 2\n"),
               Catch::Contains("inf.off:4: vertex coordinate '-inf' is not a finite number"));
    // Binary: the float reaches validation, which names the vertex.
    // (STL cannot carry one: its reader welds a NaN corner onto some other vertex.)
    const std::string ply = loadError("nan", "nan.ply",
                                      binaryPly({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, NAN}},
                                                {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}));
    CHECK_THAT(ply, Catch::Contains("nan.ply: vertex 3 has a non-finite coordinate (0, 0, nan)"));
    CHECK_THAT(ply, !Catch::Contains("--repair-surface"));
  }
  SECTION("zero-area face") {
    // Square 0-3 and a needle (1, 0, 4) along the X axis through 0 and 1.
    const std::string text =
        "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n3 0 1 2\n3 0 2 3\n3 1 0 4\n";
    const std::string error = loadError("zero-area", "needle.off", text);
    CHECK_THAT(error, Catch::Contains("needle.off: face 2 (vertices 1, 0, 4) near (1, 0, 0) has "
                                      "zero area (degenerate)"));
    CHECK_THAT(error, Catch::Contains("hint: --repair-surface fixes this"));
    SurfaceRepairReport report;
    SurfaceMesh m;
    CHECK(loadError("zero-area", "needle.off", text, true, &report, &m).empty());
    CHECK(report.degenerateFaces == 1);
    CHECK(report.isolatedVertices == 1);  // vertex 4 only belonged to the needle
    CHECK(m.faceCount() == 2);
    CHECK(m.vertexCount() == 4);
    // A face using one vertex twice is degenerate too.
    CHECK_THAT(loadError("zero-area", "twice.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n"),
               Catch::Contains("face 0 uses vertex 1 twice (degenerate)"));
  }
  SECTION("duplicate face") {
    const std::string text = "OFF\n4 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n3 1 2 0\n";
    CHECK_THAT(loadError("duplicate", "dup.off", text),
               Catch::Contains("faces 0 and 2 have the same corners (duplicate face)"));
    SurfaceRepairReport report;
    CHECK(loadError("duplicate", "dup.off", text, true, &report).empty());
    CHECK(report.duplicateFaces == 1);
  }
  SECTION("non-manifold edge: three faces on one edge") {
    const std::string text =
        "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n"
        "3 0 1 2\n3 1 0 3\n3 0 1 4\n";
    const std::string error = loadError("nm-edge", "fin.off", text);
    CHECK_THAT(error, Catch::Contains("fin.off: edge (0, 1) at (0, 0, 0) is shared by 3 faces "
                                      "(non-manifold): faces 0, 1, 2"));
    CHECK_THAT(error, !Catch::Contains("hint: --repair-surface"));
    CHECK_THAT(error, Catch::Contains("never repaired"));
    const std::string repaired = loadError("nm-edge", "fin.off", text, true);
    CHECK_THAT(repaired, Catch::Contains("is shared by 3 faces (non-manifold)"));
  }
  SECTION("non-manifold vertex: a bow-tie") {
    const std::string text =
        "OFF\n5 2 0\n0 0 0\n1 -0.5 0\n1 0.5 0\n-1 0.5 0\n-1 -0.5 0\n"
        "3 0 1 2\n3 0 3 4\n";
    const std::string error = loadError("bow-tie", "bowtie.off", text);
    CHECK_THAT(error, Catch::Contains("bowtie.off: vertex 0 at (0, 0, 0) is where 2 separate fans "
                                      "of faces meet (non-manifold vertex)"));
    CHECK_THAT(error, !Catch::Contains("hint:"));
    CHECK_THAT(loadError("bow-tie", "bowtie.off", text, true),
               Catch::Contains("(non-manifold vertex)"));
  }
  SECTION("isolated vertex") {
    const std::string text = "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n7 7 7\n3 0 1 2\n";
    const std::string error = loadError("isolated", "lonely.off", text);
    CHECK_THAT(error, Catch::Contains("lonely.off: vertex 3 at (7, 7, 7) belongs to no face "
                                      "(isolated vertex)"));
    CHECK_THAT(error, Catch::Contains("hint: --repair-surface fixes this (a trial repair dropped 1 "
                                      "isolated vertex)"));
    SurfaceRepairReport report;
    SurfaceMesh m;
    CHECK(loadError("isolated", "lonely.off", text, true, &report, &m).empty());
    CHECK(report.isolatedVertices == 1);
    CHECK(m.vertexCount() == 3);
  }
  SECTION("flipped face") {
    std::string text = kGridOff;
    text.replace(text.find("3 4 5 8"), 7, "3 4 8 5");  // face 6 reversed
    const std::string error = loadError("flipped", "grid.off", text);
    CHECK_THAT(error, Catch::Contains("(inconsistent orientation)"));
    CHECK_THAT(error, Catch::Contains("faces 3 and 6 both run along edge (4, 5) from 5 to 4"));
    CHECK_THAT(error, Catch::Contains(
                          "hint: --repair-surface fixes this (a trial repair flipped 1 face)"));
    SurfaceRepairReport report;
    SurfaceMesh m;
    CHECK(loadError("flipped", "grid.off", text, true, &report, &m).empty());
    CHECK(report.flippedFaces == 1);
    for (const Vec3& n : m.faceNormals) CHECK(n.z() == Approx(1.0));
  }
}

TEST_CASE("loading: formats, polygons, welding", "[surface]") {
  SurfaceMesh m;
  std::string error;
  const fs::path dir = scratchDir("formats");
  SECTION("an OBJ cube of quads is split into 12 triangles, closed") {
    writeText(dir / "cube.obj",
              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
              "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    INFO(error);
    REQUIRE(loadSurface((dir / "cube.obj").string(), m, error));
    CHECK(m.faceCount() == 12);
    checkSound(m, true, 2);
    CHECK(signedVolume(m) == Approx(1.0));
  }
  SECTION("ASCII STL corners are welded into shared vertices") {
    const Vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const int tris[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    std::string stl = "solid tet\n";
    for (const auto& t : tris) {
      stl += "facet normal 0 0 0\nouter loop\n";
      for (int k : t)
        stl += "vertex " + std::to_string(p[k].x()) + " " + std::to_string(p[k].y()) + " " +
               std::to_string(p[k].z()) + "\n";
      stl += "endloop\nendfacet\n";
    }
    stl += "endsolid tet\n";
    writeText(dir / "tet.stl", stl);
    INFO(error);
    REQUIRE(loadSurface((dir / "tet.stl").string(), m, error));
    CHECK(m.vertexCount() == 4);
    checkSound(m, true, 2);
  }
  SECTION("a PLY file") {
    writeText(dir / "tri.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
              "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    INFO(error);
    REQUIRE(loadSurface((dir / "tri.ply").string(), m, error));
    checkSound(m, false, 1);
  }
  SECTION("an inside-out closed surface loads; repair turns it outwards") {
    writeText(dir / "inside-out.off",
              "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n");
    REQUIRE(loadSurface((dir / "inside-out.off").string(), m, error));
    CHECK(signedVolume(m) < 0);
    SurfaceLoadOptions options;
    options.repair = true;
    SurfaceRepairReport report;
    REQUIRE(loadSurface((dir / "inside-out.off").string(), m, error, options, &report));
    CHECK(report.flippedFaces == 4);
    CHECK(signedVolume(m) > 0);
  }
}

// ---- real meshes (scripts/fetch-test-meshes.sh) ----

TEST_CASE("real meshes load, with the right counts and topology", "[surface]") {
  struct Expected {
    const char* file;
    size_t vertices, faces;
    long chi;
    size_t boundary;  // boundary edges
  };
  const Expected sound[] = {
      {"bunny00.off", 37706, 75408, 2, 0},
      {"armadillo.off", 26002, 52000, 2, 0},
      {"elephant.off", 2775, 5558, -4, 0},
      {"refined_elephant.off", 44460, 88928, -4, 0},
      {"elephant-with-holes.off", 2798, 4463, -110, 1353},
      {"ChineseDragon-10kv.off", 10000, 19994, 0, 6},
      {"double-torus-example.off", 231, 466, -2, 0},
      {"sphere.ply", 162, 320, 2, 0},
      {"sphere.stl", 162, 320, 2, 0},
      // Comments before the keyword and after numbers, colours after coordinates and
      // indices, a pentagon: an octagon split into 6 triangles.
      {"mesh_with_colors.off", 8, 6, 1, 8},
  };
  for (const auto& e : sound) {
    INFO(e.file);
    SurfaceMesh m;
    std::string error;
    const bool ok = loadSurface(meshFile(e.file).string(), m, error);
    INFO(error);
    REQUIRE(ok);
    CHECK(m.vertexCount() == e.vertices);
    CHECK(m.faceCount() == e.faces);
    CHECK(boundaryEdges(m) == e.boundary);
    checkSound(m, e.boundary == 0, e.chi);
    // Nothing left for a repair to do on a sound mesh but, perhaps, turning it outwards.
    SurfaceMesh copy = m;
    const SurfaceRepairReport report = repairSurface(copy);
    CHECK(report.degenerateFaces + report.duplicateFaces + report.isolatedVertices == 0);
  }
}

TEST_CASE("broken real meshes fail with the expected message", "[surface]") {
  struct Expected {
    const char* file;
    const char* message;
    bool repairable;
    size_t facesAfterRepair;
  };
  const Expected broken[] = {
      {"degtri_sliding.off", "has zero area (degenerate)", true, 4},
      {"mpi.off", "has zero area (degenerate)", true, 178},
      {"cube-ouvert.off", "vertex 8 at (1, 2, 1) belongs to no face (isolated vertex)", true, 10},
      {"tet-shuffled.off", "(inconsistent orientation)", true, 4},
      {"polygon_mesh.off", "(non-manifold vertex)", false, 0},
      {"pig.stl", "and 411 more: 411 non-manifold vertices", false, 0},
      {"b9.ply", "the surface has no faces", false, 0},
  };
  for (const auto& e : broken) {
    INFO(e.file);
    const std::string path = meshFile(e.file).string();
    SurfaceMesh m;
    std::string error;
    CHECK_FALSE(loadSurface(path, m, error));
    CHECK(m.faceCount() == 0);
    CHECK_THAT(error, Catch::Contains(std::string(e.file) + ": ") && Catch::Contains(e.message));
    CHECK((error.find("hint: --repair-surface fixes this") != std::string::npos) == e.repairable);
    SurfaceLoadOptions options;
    options.repair = true;
    const bool ok = loadSurface(path, m, error, options);
    INFO(error);
    CHECK(ok == e.repairable);
    if (ok) {
      CHECK(m.faceCount() == e.facesAfterRepair);
      checkNeighboursPointBack(m);
    }
  }
}

// ---- point location ----

TEST_CASE("closestPoint matches brute force", "[surface]") {
  std::mt19937 rng(7);
  for (const SurfaceMesh& m : {genus2(1.0, 0.4, 2), torus(1.0, 0.3, 12), plane(2.0, 1.0, 8)}) {
    const SurfaceLocator locator(m);
    const Vec3 lo = m.boundsMin - Vec3::Constant(0.5), hi = m.boundsMax + Vec3::Constant(0.5);
    std::uniform_real_distribution<double> u(0, 1);
    size_t bad = 0;
    for (int i = 0; i < 300; ++i) {
      const Vec3 p(lo.x() + u(rng) * (hi.x() - lo.x()), lo.y() + u(rng) * (hi.y() - lo.y()),
                   lo.z() + u(rng) * (hi.z() - lo.z()));
      double best = INFINITY;
      for (const auto& t : m.faces) {
        Vec3 bary;
        const Vec3 q =
            closestPointOnTriangle(p, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], bary);
        best = std::min(best, (q - p).norm());
      }
      double distance = 0;
      const SurfacePoint s = locator.closestPoint(p, &distance);
      REQUIRE(s.valid());
      const bool baryOk = s.bary.minCoeff() >= 0 && std::abs(s.bary.sum() - 1) < 1e-12;
      if (!baryOk || std::abs(distance - best) > 1e-12 ||
          std::abs((s.position(m) - p).norm() - distance) > 1e-12)
        ++bad;
    }
    CHECK(bad == 0);
    // A point on the surface finds itself.
    const SurfacePoint inside{int(m.faceCount() / 2), Vec3(0.2, 0.3, 0.5)};
    const SurfacePoint found = closestPoint(m, inside.position(m));
    CHECK((found.position(m) - inside.position(m)).norm() < 1e-12);
  }
  const SurfaceMesh empty;
  CHECK_FALSE(SurfaceLocator(empty).closestPoint(Vec3::Zero()).valid());
}

TEST_CASE("closestPointOnTriangle: corners, edges and inside", "[surface]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  Vec3 bary;
  CHECK(closestPointOnTriangle(Vec3(-1, -1, 3), a, b, c, bary).isApprox(a));
  CHECK(bary == Vec3(1, 0, 0));
  CHECK(closestPointOnTriangle(Vec3(2, -0.5, 0), a, b, c, bary).isApprox(b));
  CHECK((closestPointOnTriangle(Vec3(0.5, -2, 1), a, b, c, bary) - Vec3(0.5, 0, 0)).norm() < 1e-15);
  CHECK(bary.isApprox(Vec3(0.5, 0.5, 0)));
  CHECK((closestPointOnTriangle(Vec3(1, 1, -1), a, b, c, bary) - Vec3(0.5, 0.5, 0)).norm() < 1e-15);
  CHECK(bary.isApprox(Vec3(0, 0.5, 0.5)));
  CHECK((closestPointOnTriangle(Vec3(0.25, 0.25, 2), a, b, c, bary) - Vec3(0.25, 0.25, 0)).norm() <
        1e-15);
  CHECK(bary.isApprox(Vec3(0.5, 0.25, 0.25)));
}

TEST_CASE("surface points at vertices and on edges", "[surface]") {
  const SurfaceMesh m = torus(1.0, 0.4, 8);
  for (int v = 0; v < int(m.vertexCount()); ++v) {
    const SurfacePoint s = atVertex(m, v);
    REQUIRE(s.valid());
    CHECK((s.position(m) - m.vertices[v]).norm() < 1e-15);
    CHECK(s.bary.maxCoeff() == 1.0);
  }
  const auto& t = m.faces[5];
  const SurfacePoint e = atEdge(m, 5, 2, 0.25);  // from corner 2 to corner 0
  CHECK((e.position(m) - (0.75 * m.vertices[t[2]] + 0.25 * m.vertices[t[0]])).norm() < 1e-15);
  CHECK(e.bary[1] == 0.0);
  SurfaceMesh withIsolated = plane(1.0, 1.0, 1);
  withIsolated.vertices.push_back(Vec3(3, 3, 3));
  withIsolated.buildTopology();
  CHECK_FALSE(atVertex(withIsolated, 4).valid());
}
