// The inverse poly-cube map (Chan & Hui 2013 §5.1): a polycube of the expected size
// around a cube, every face-let point carried onto the surface by a ray (no fallback),
// seamless across face-let edges and vertices, covering the surface, with unit normals and
// tangents in the tangent plane; bad input refused with a clear message.
#include "../box_surface.h"
#include "runtime/evolve/polycube_map.h"

#include "runtime/surface/load_surface.h"
#include "runtime/surface/procedural.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace fgsg::rt::evolve;
using fgsg::rt::Vec3;
using fgsg::rt::surface::SurfaceMesh;

namespace {

SurfaceMesh box(const Vec3& lo, const Vec3& hi) { return fgsg::test::boxSurface(lo, hi); }

// Distance from p to triangle (a, b, c): to the plane when p projects inside, else to the
// nearest edge.
double distanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a).normalized();
  const Vec3 q = p - n.dot(p - a) * n;
  const bool inside = n.dot((b - a).cross(q - a)) >= 0 && n.dot((c - b).cross(q - b)) >= 0 &&
                      n.dot((a - c).cross(q - c)) >= 0;
  if (inside) return std::abs(n.dot(p - a));
  const auto seg = [&](const Vec3& s, const Vec3& e) {
    const double t = std::clamp((p - s).dot(e - s) / (e - s).squaredNorm(), 0.0, 1.0);
    return (p - (s + t * (e - s))).norm();
  };
  return std::min({seg(a, b), seg(b, c), seg(c, a)});
}

double diagonal(const SurfaceMesh& m) {
  Vec3 lo = m.vertices[0], hi = m.vertices[0];
  for (const Vec3& p : m.vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

// A face-let's corners (a, b) in {0,1}^2 with their lattice points (cell-unit integers),
// from the documented convention: u along axis + 1, v along axis + 2 for sign +1, the other
// way round for sign -1.
struct Corner {
  std::array<int, 3> lattice;
  double a, b;
};
std::array<Corner, 4> corners(const PolycubeMap& pc, const Facelet& f) {
  const Vec3 o = (f.origin - pc.gridOrigin()) / pc.cellSize();
  const int ua = f.sign > 0 ? (f.axis + 1) % 3 : (f.axis + 2) % 3;
  const int va = f.sign > 0 ? (f.axis + 2) % 3 : (f.axis + 1) % 3;
  std::array<Corner, 4> c;
  for (int k = 0; k < 4; ++k) {
    const int a = k & 1, b = k >> 1;
    std::array<int, 3> l = {int(std::lround(o.x())), int(std::lround(o.y())), int(std::lround(o.z()))};
    l[size_t(ua)] += a;
    l[size_t(va)] += b;
    c[size_t(k)] = {l, double(a), double(b)};
  }
  return c;
}

struct SeamReport {
  size_t edges = 0, sharedEdges = 0, vertices = 0;
  double edgeError = 0, vertexError = 0;  // max distance, relative to the bbox diagonal
};

// Maps `samples` points along every face-let edge (ends included) from every face-let
// holding it, and every lattice vertex from every face-let holding it, and measures how far
// the images of one point lie apart.
SeamReport measureSeams(const PolycubeMap& pc, double diag, int samples) {
  using Key = std::array<int, 6>;
  std::map<Key, std::vector<std::pair<size_t, std::array<Corner, 2>>>> edges;
  std::map<std::array<int, 3>, std::vector<std::pair<size_t, Corner>>> vertices;
  const auto& fl = pc.facelets();
  for (size_t f = 0; f < fl.size(); ++f) {
    const auto c = corners(pc, fl[f]);
    for (const auto& [i, j] : {std::pair{0, 1}, {1, 3}, {3, 2}, {2, 0}}) {
      Corner p = c[size_t(i)], q = c[size_t(j)];
      if (q.lattice < p.lattice) std::swap(p, q);  // run every edge from its smaller end
      edges[{p.lattice[0], p.lattice[1], p.lattice[2], q.lattice[0], q.lattice[1], q.lattice[2]}].push_back(
          {f, {p, q}});
    }
    for (const Corner& k : c) vertices[k.lattice].push_back({f, k});
  }
  SeamReport r;
  r.edges = edges.size();
  for (const auto& [key, users] : edges) {
    if (users.size() < 2) continue;
    ++r.sharedEdges;
    for (int s = 0; s <= samples; ++s) {
      const double t = double(s) / samples;
      Vec3 first;
      for (size_t u = 0; u < users.size(); ++u) {
        const auto& [f, e] = users[u];
        const MappedPoint m = pc.map(f, e[0].a + t * (e[1].a - e[0].a), e[0].b + t * (e[1].b - e[0].b));
        if (u == 0) first = m.position;
        else r.edgeError = std::max(r.edgeError, (m.position - first).norm() / diag);
      }
    }
  }
  r.vertices = vertices.size();
  for (const auto& [key, users] : vertices) {
    const Vec3 first = pc.map(users[0].first, users[0].second.a, users[0].second.b).position;
    for (const auto& [f, c] : users)
      r.vertexError = std::max(r.vertexError, (pc.map(f, c.a, c.b).position - first).norm() / diag);
  }
  return r;
}

// Maps an n x n grid of points on every face-let (borders included); calls `each` on them.
template <class F>
void forGrid(const PolycubeMap& pc, int n, F each) {
  for (size_t f = 0; f < pc.facelets().size(); ++f)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) each(f, pc.map(f, double(i) / (n - 1), double(j) / (n - 1)));
}

size_t missesOnGrid(const PolycubeMap& pc, int n) {
  size_t misses = 0;
  forGrid(pc, n, [&](size_t, const MappedPoint& m) { misses += !m.hit; });
  return misses;
}

void checkFrames(const PolycubeMap& pc, int n) {
  double worst = 0;
  forGrid(pc, n, [&](size_t, const MappedPoint& m) {
    worst = std::max({worst, std::abs(m.normal.norm() - 1), std::abs(m.tangentU.norm() - 1),
                      std::abs(m.tangentV.norm() - 1), std::abs(m.tangentU.dot(m.normal)),
                      std::abs(m.tangentV.dot(m.normal))});
  });
  CHECK(worst < 1e-9);
}

std::string meshPath(const std::string& name) {
  // tests/data/meshes is filled by scripts/fetch-test-meshes.sh (see tests/data/README.md).
  return std::string(FGSG_SOURCE_DIR) + "/tests/data/meshes/" + name;
}

}  // namespace

TEST_CASE("polycube around a cube: face-let count and every point on the surface", "[polycube]") {
  const SurfaceMesh cube = box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  SECTION("cube sides on lattice planes") {
    // Cell 0.25, the cube spans lattice 2..10: cells 1..10 are touched, 2..9 have their
    // centre inside: 8^3 solid cells, the polycube is the cube itself.
    PolycubeMap pc(cube, {.resolution = 8});
    CHECK(pc.cellSize() == 0.25);
    CHECK(pc.gridCells() == std::array<int, 3>{12, 12, 12});
    CHECK(pc.solidCells() == 512);
    CHECK(pc.facelets().size() == 6 * 64);
  }
  SECTION("cube sides between lattice planes") {
    // Cell 0.3: the cube spans lattice 2..8.67, cells 1..8 touched (cell 1 at its face);
    // centres 2.5..8.5 inside: 7^3 solid cells.
    PolycubeMap pc(cube, {.cellSize = 0.3});
    CHECK(pc.solidCells() == 343);
    CHECK(pc.facelets().size() == 6 * 49);
  }
  for (const int res : {1, 3, 8}) {
    PolycubeMap pc(cube, {.resolution = res});
    const double diag = diagonal(cube);
    double worst = 0;
    size_t misses = 0;
    forGrid(pc, 9, [&](size_t, const MappedPoint& m) {
      misses += !m.hit;
      double d = 1e300;
      for (const auto& f : cube.faces)
        d = std::min(d, distanceToTriangle(m.position, cube.vertices[f[0]], cube.vertices[f[1]], cube.vertices[f[2]]));
      worst = std::max(worst, d / diag);
      // The reported face and barycentric coordinates give the same point.
      const auto& f = cube.faces[size_t(m.face)];
      const Vec3 p = m.bary[0] * cube.vertices[f[0]] + m.bary[1] * cube.vertices[f[1]] + m.bary[2] * cube.vertices[f[2]];
      worst = std::max(worst, (p - m.position).norm() / diag);
    });
    INFO("resolution " << res);
    CHECK(misses == 0);
    CHECK(pc.fallbackCount() == 0);
    CHECK(worst < 1e-9);
    CHECK(measureSeams(pc, diag, 8).edgeError < 1e-9);
  }
}

TEST_CASE("polycube map of a sphere: every point hits, seamless, covers the surface", "[polycube]") {
  const SurfaceMesh sphere = fgsg::rt::surface::sphere(1.0, 4);
  const double diag = diagonal(sphere);
  for (const int res : {4, 8, 16}) {
    PolycubeMap pc(sphere, {.resolution = res});
    INFO("resolution " << res << ", " << pc.facelets().size() << " face-lets");
    CHECK(missesOnGrid(pc, 9) == 0);
    const SeamReport s = measureSeams(pc, diag, 8);
    INFO("shared edges " << s.sharedEdges << " of " << s.edges);
    CHECK(s.sharedEdges == s.edges);  // a closed polycube: every edge between face-lets
    CHECK(s.edgeError < 1e-9);
    CHECK(s.vertexError < 1e-9);
    checkFrames(pc, 5);
  }
  SECTION("coverage: a dense sampling reaches every face") {
    PolycubeMap pc(sphere, {.resolution = 8});
    std::vector<uint8_t> reached(sphere.faceCount(), 0);
    forGrid(pc, 32, [&](size_t, const MappedPoint& m) { reached[size_t(m.face)] = 1; });
    double area = 0, total = 0;
    for (size_t f = 0; f < sphere.faceCount(); ++f) {
      total += sphere.faceAreas[f];
      area += reached[f] * sphere.faceAreas[f];
    }
    WARN("sphere, resolution 8, 32x32 samples per face-let: " << std::count(reached.begin(), reached.end(), 1)
                                                              << " of " << sphere.faceCount()
                                                              << " faces reached, area fraction " << area / total);
    CHECK(area / total > 0.99);
  }
}

TEST_CASE("polycube map of a torus: every point hits, seamless", "[polycube]") {
  const SurfaceMesh torus = fgsg::rt::surface::torus(1.0, 0.4, 32);
  const double diag = diagonal(torus);
  for (const int res : {8, 16}) {
    PolycubeMap pc(torus, {.resolution = res});
    INFO("resolution " << res << ", " << pc.facelets().size() << " face-lets");
    CHECK(missesOnGrid(pc, 9) == 0);
    const SeamReport s = measureSeams(pc, diag, 8);
    CHECK(s.sharedEdges == s.edges);
    CHECK(s.edgeError < 1e-9);
    CHECK(s.vertexError < 1e-9);
    checkFrames(pc, 5);
  }
}

TEST_CASE("polycube map of open surfaces: a plane and a cylinder", "[polycube]") {
  for (const SurfaceMesh& m : {fgsg::rt::surface::plane(2, 2, 8), fgsg::rt::surface::cylinder(1, 2, 24)}) {
    PolycubeMap pc(m, {.resolution = 8});
    const SeamReport s = measureSeams(pc, diagonal(m), 4);
    CHECK(s.edgeError < 1e-9);
    CHECK(s.vertexError < 1e-9);
    checkFrames(pc, 5);
    WARN("open surface: " << pc.facelets().size() << " face-lets, misses on a 9x9 grid " << missesOnGrid(pc, 9));
  }
}

TEST_CASE("polycube map: directions point into the solid and are continuous", "[polycube]") {
  PolycubeMap pc(fgsg::rt::surface::torus(1.0, 0.4, 16), {.resolution = 6});
  for (size_t f = 0; f < pc.facelets().size(); ++f)
    for (const double a : {0.0, 0.3, 1.0})
      for (const double b : {0.0, 0.5, 1.0}) {
        const Vec3 d = pc.projectionDirection(f, a, b);
        CHECK(std::abs(d.norm() - 1) < 1e-12);
        CHECK(d.dot(pc.facelets()[f].normal) < 0);
      }
}

TEST_CASE("polycube map: bad input is refused with a clear message", "[polycube]") {
  using Catch::Matchers::Contains;
  const SurfaceMesh sphere = fgsg::rt::surface::sphere(1.0, 1);
  CHECK_THROWS_WITH(PolycubeMap(SurfaceMesh{}), Contains("empty"));
  CHECK_THROWS_AS(PolycubeMap(SurfaceMesh{}), std::invalid_argument);
  SurfaceMesh raw;
  raw.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  raw.faces = {{0, 1, 2}};
  CHECK_THROWS_WITH(PolycubeMap(raw), Contains("buildTopology"));
  CHECK_THROWS_WITH(PolycubeMap(sphere, {.resolution = 0}), Contains("resolution must be in 1..256"));
  CHECK_THROWS_WITH(PolycubeMap(sphere, {.resolution = 1000}), Contains("got 1000"));
  CHECK_THROWS_AS(PolycubeMap(sphere, {.resolution = 1000}), std::invalid_argument);
  CHECK_THROWS_WITH(PolycubeMap(sphere, {.cellSize = -1}), Contains("cellSize must be finite and > 0"));
  CHECK_THROWS_WITH(PolycubeMap(sphere, {.cellSize = 1e-3}), Contains("at most 256"));
  CHECK_THROWS_WITH(PolycubeMap(sphere, {.resolution = 8, .maxFacelets = 10}), Contains("more than 10 face-lets"));
  SurfaceMesh point = raw;
  point.vertices = {Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)};
  point.buildTopology();
  CHECK_THROWS_WITH(PolycubeMap(point), Contains("no extent"));

  PolycubeMap pc(sphere, {.resolution = 2});
  CHECK_THROWS_AS(pc.map(pc.facelets().size(), 0, 0), std::out_of_range);
  CHECK_THROWS_AS(pc.map(0, -0.1, 0), std::out_of_range);
  CHECK_THROWS_AS(pc.map(0, 0, std::nan("")), std::out_of_range);
}

// At resolution 8 the ears are about a cell thick; lines from the face-lets around them can
// pass beside them (the nearest-point fallback then takes over, seamless all the same).
TEST_CASE("polycube map of the bunny: (almost) every point hits, seamless", "[polycube]") {
  const std::string path = meshPath("bunny00.off");
  if (!std::filesystem::exists(path)) FAIL(path << " is missing: run scripts/fetch-test-meshes.sh");
  SurfaceMesh bunny;
  std::string error;
  REQUIRE(fgsg::rt::surface::loadSurface(path, bunny, error));
  const double diag = diagonal(bunny);
  for (const auto& [res, allowed] : {std::pair{8, 0.02}, {16, 1e-3}, {32, 1e-3}}) {
    const auto t0 = std::chrono::steady_clock::now();
    PolycubeMap pc(bunny, {.resolution = res});
    const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto t1 = std::chrono::steady_clock::now();
    const size_t misses = missesOnGrid(pc, 9);
    const double mapping = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    const SeamReport s = measureSeams(pc, diag, 8);
    WARN("bunny, resolution " << res << ": " << pc.facelets().size() << " face-lets, " << pc.solidCells()
                              << " solid cells, built in " << build * 1e3 << " ms; "
                              << 81 * pc.facelets().size() / mapping << " map() per second (one thread); "
                              << misses << " fallbacks of " << 81 * pc.facelets().size()
                              << "; seam error edges " << s.edgeError << ", vertices " << s.vertexError);
    CHECK(double(misses) / double(81 * pc.facelets().size()) < allowed);
    CHECK(s.sharedEdges == s.edges);
    CHECK(s.edgeError < 1e-9);
    CHECK(s.vertexError < 1e-9);
    checkFrames(pc, 5);
  }
}

TEST_CASE("polycube map: map() from several threads gives the serial results", "[polycube]") {
  const PolycubeMap pc(fgsg::rt::surface::torus(1.0, 0.4, 24), {.resolution = 10});
  const size_t n = pc.facelets().size();
  std::vector<Vec3> serial(n * 25), parallel(n * 25);
  const auto run = [&](std::vector<Vec3>& out, size_t from, size_t step) {
    for (size_t f = from; f < n; f += step)
      for (int k = 0; k < 25; ++k) out[f * 25 + size_t(k)] = pc.map(f, (k % 5) / 4.0, (k / 5) / 4.0).position;
  };
  run(serial, 0, 1);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < 4; ++t) threads.emplace_back([&, t] { run(parallel, t, 4); });
  for (auto& t : threads) t.join();
  CHECK(serial == parallel);
}
