// buildAtlas: charts, parametrization and packing on a cube and on real meshes, checked by
// atlas_checks.h (inside the unit square, gutters by rasterization, nothing flipped), plus
// uniform texel density, bounded conformal distortion and determinism.
#include "runtime/atlas/atlas.h"
#include "runtime/surface/procedural.h"

#include "atlas_checks.h"

#include <catch2/catch.hpp>
#include <tbb/task_arena.h>

#include <chrono>
#include <cstdio>

using namespace fgsg::rt;
using fgsg::test::AtlasFigures;
using fgsg::test::checkAtlas;
using fgsg::test::loadTestMesh;

namespace {

// The unit cube, each side split into n x n squares of two triangles, outward.
surface::SurfaceMesh cube(int n) {
  surface::SurfaceMesh m;
  auto vertex = [&](const Vec3& p) {
    for (size_t i = 0; i < m.vertices.size(); ++i)
      if ((m.vertices[i] - p).norm() < 1e-12) return int(i);
    m.vertices.push_back(p);
    return int(m.vertices.size() - 1);
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      Vec3 normal = Vec3::Zero();
      normal[axis] = side ? 1 : -1;
      Vec3 a = Vec3::Zero(), b = Vec3::Zero();
      a[(axis + 1) % 3] = 1;
      b[(axis + 2) % 3] = 1;
      if (a.cross(b).dot(normal) < 0) std::swap(a, b);
      const Vec3 origin = Vec3::Constant(0.5) + 0.5 * normal - 0.5 * a - 0.5 * b;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto at = [&](int di, int dj) { return vertex(origin + a * double(i + di) / n + b * double(j + dj) / n); };
          const int p = at(0, 0), q = at(1, 0), r = at(1, 1), s = at(0, 1);
          m.faces.push_back({p, q, r});
          m.faces.push_back({p, r, s});
        }
    }
  m.buildTopology();
  return m;
}

atlas::Atlas build(const surface::SurfaceMesh& mesh, const atlas::AtlasOptions& options = {}) {
  atlas::Atlas a;
  std::string error;
  INFO(error);
  REQUIRE(atlas::buildAtlas(mesh, options, a, error));
  return a;
}

void requireUniformDensity(const AtlasFigures& figures) {
  for (double d : figures.density) REQUIRE(d == Approx(figures.density[0]).epsilon(1e-9));
}

}  // namespace

TEST_CASE("a closed cube has six charts, each an undistorted square", "[atlas]") {
  for (int n : {1, 4}) {
    INFO(n << " x " << n << " squares per side");
    const surface::SurfaceMesh mesh = cube(n);
    std::vector<std::string> problems;
    REQUIRE(surface::validateSurface(mesh, problems));
    const atlas::Atlas a = build(mesh);
    REQUIRE(a.chartCount == 6);
    for (size_t f = 0; f < mesh.faces.size(); ++f) REQUIRE(a.faceChart[f] == a.faceChart[f - f % (2 * n * n)]);
    const AtlasFigures figures = checkAtlas(mesh, a, 2);
    requireUniformDensity(figures);
    REQUIRE(figures.maxStretch == Approx(1.0).epsilon(1e-9));
    // Six equal squares: two rows of three fill the image better than any other shelf.
    REQUIRE(figures.coverage > 0.6);
  }
}

TEST_CASE("atlases of real meshes: packed, gutters kept, uniform density, bounded distortion", "[atlas]") {
  struct Case {
    const char* name;
    double meanStretchBound;
  };
  // Measured mean stretch (largest over smallest singular value, area-weighted): bunny
  // 1.006, elephant 1.028, armadillo 1.025; the bounds keep a margin of about 5%.
  for (const Case& c : {Case{"bunny00.off", 1.06}, Case{"elephant.off", 1.08}, Case{"armadillo.off", 1.08}}) {
    INFO(c.name);
    const surface::SurfaceMesh mesh = loadTestMesh(c.name);
    atlas::AtlasOptions options;
    options.resolution = 1024;
    const auto start = std::chrono::steady_clock::now();
    const atlas::Atlas a = build(mesh, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const AtlasFigures figures = checkAtlas(mesh, a, options.gutterTexels);
    std::printf("atlas %s: %zu faces, %d charts, %.3f s, coverage %.3f, stretch mean %.4f max %.2f\n",
                c.name, mesh.faces.size(), a.chartCount, seconds, figures.coverage, figures.meanStretch,
                figures.maxStretch);
    requireUniformDensity(figures);
    REQUIRE(figures.meanStretch < c.meanStretchBound);
    REQUIRE(figures.coverage > 0.3);  // measured 0.41, 0.42, 0.375
  }
}

TEST_CASE("an atlas is deterministic, on any number of threads", "[atlas]") {
  const surface::SurfaceMesh mesh = loadTestMesh("elephant.off");
  const atlas::Atlas a = build(mesh), b = build(mesh);
  atlas::Atlas single;
  tbb::task_arena(1).execute([&] { single = build(mesh); });
  for (const atlas::Atlas* other : {&b, static_cast<const atlas::Atlas*>(&single)}) {
    REQUIRE(a.chartCount == other->chartCount);
    REQUIRE(a.faceChart == other->faceChart);
    REQUIRE(a.cornerUV == other->cornerUV);
  }
}

TEST_CASE("charts that are not disks are split: a closed sphere at 180 degrees", "[atlas]") {
  // Every face is within 180 degrees of every other, so region growing takes the whole
  // sphere as one chart; it must be cut until each piece is a disk that lies flat.
  const surface::SurfaceMesh mesh = surface::sphere(1.0, 2);
  atlas::AtlasOptions options;
  options.maxNormalDeviation = 180;
  const atlas::Atlas a = build(mesh, options);
  REQUIRE(a.chartCount >= 2);
  requireUniformDensity(checkAtlas(mesh, a, options.gutterTexels));
}

TEST_CASE("a larger gutter and a smaller image still keep charts apart", "[atlas]") {
  const surface::SurfaceMesh mesh = loadTestMesh("elephant.off");
  atlas::AtlasOptions options;
  options.resolution = 256;
  options.gutterTexels = 3;
  const atlas::Atlas a = build(mesh, options);
  REQUIRE(a.resolution == 256);
  checkAtlas(mesh, a, 3);
}

TEST_CASE("atlas options out of range are refused with a message", "[atlas]") {
  const surface::SurfaceMesh mesh = cube(1);
  atlas::Atlas a;
  std::string error;
  atlas::AtlasOptions options;
  options.gutterTexels = 0;
  REQUIRE_FALSE(atlas::buildAtlas(mesh, options, a, error));
  REQUIRE(error == "atlas: the gutter must be at least one texel (indirection pixels live there), not 0");
  options = {};
  options.resolution = 4;
  REQUIRE_FALSE(atlas::buildAtlas(mesh, options, a, error));
  REQUIRE(error == "atlas: a resolution of 4 texels cannot hold a chart with a gutter of 2 texels (at least 5, at most 1048576)");
  options = {};
  options.maxNormalDeviation = 0;
  REQUIRE_FALSE(atlas::buildAtlas(mesh, options, a, error));
  REQUIRE(error.find("normal deviation must be within (0, 180]") != std::string::npos);
}

TEST_CASE("too many charts for the image is a clear error", "[atlas]") {
  // 6 charts need 3 x 3 texels each with a gutter of 2: a 7-texel image holds one.
  const surface::SurfaceMesh mesh = cube(1);
  atlas::AtlasOptions options;
  options.resolution = 7;
  atlas::Atlas a;
  std::string error;
  REQUIRE_FALSE(atlas::buildAtlas(mesh, options, a, error));
  REQUIRE(error ==
          "atlas: 6 charts do not fit into a 7x7 geometry image with a gutter of 2 texels, even at one "
          "texel each: use a larger resolution (or, for a generated atlas, a larger normal deviation)");
  REQUIRE(a.chartCount == 0);
}
