// fgsg atlas --export-uv (runtime/texture/atlas_uv_export.h): the OBJ holds the surface
// and, per face corner, exactly the coordinate texture contexts are read at; a vertex has
// one vt per chart it lies in; and an image painted through the OBJ's UVs lands where
// the atlas itself paints (paintMask, what --paint writes).
#include "runtime/marching/marching_surface.h"
#include "runtime/surface/procedural.h"
#include "runtime/texture/atlas_uv_export.h"
#include "runtime/texture/paint_mask.h"
#include "tests/unit/runtime/scratch_files.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace fgsg::rt;
namespace fs = std::filesystem;

namespace {

struct Obj {
  std::vector<Vec3> v;
  std::vector<atlas::Vec2> vt;
  std::vector<std::array<int, 3>> f, ft;  // 0-based
};

// A strict reader of the subset written: v, vt, f a/ta b/tb c/tc, # comments.
Obj parseObj(const std::string& text) {
  Obj obj;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    std::string tag;
    l >> tag;
    if (tag == "v") {
      Vec3 p;
      l >> p.x() >> p.y() >> p.z();
      obj.v.push_back(p);
    } else if (tag == "vt") {
      atlas::Vec2 uv;
      l >> uv.x() >> uv.y();
      obj.vt.push_back(uv);
    } else if (tag == "f") {
      std::array<int, 3> f{}, t{};
      char slash = 0;
      for (int k = 0; k < 3; ++k) {
        l >> f[k] >> slash >> t[k];
        REQUIRE(slash == '/');
        --f[k], --t[k];
      }
      obj.f.push_back(f);
      obj.ft.push_back(t);
    } else {
      REQUIRE(tag.rfind("#", 0) == 0);
      continue;
    }
    REQUIRE_FALSE(l.fail());
    std::string rest;
    REQUIRE_FALSE(l >> rest);  // nothing more on the line
  }
  return obj;
}

std::shared_ptr<const marching::MarchingSurface> sphereSurface() {
  std::string error;
  marching::MarchingOptions options;
  options.resolution = 512;
  auto s = marching::MarchingSurface::prepare(surface::sphere(1.0, 3), options, error);
  INFO(error);
  REQUIRE(s);
  return s;
}

}  // namespace

TEST_CASE("the exported OBJ carries the atlas's own texture coordinates", "[marching][export-uv]") {
  const auto s = sphereSurface();
  const auto& mesh = s->mesh();
  const Obj obj = parseObj(texture::atlasUvObj(*s));
  REQUIRE(obj.v.size() == mesh.vertices.size());
  REQUIRE(obj.f.size() == mesh.faceCount());
  REQUIRE(obj.ft.size() == mesh.faceCount());
  for (size_t i = 0; i < obj.v.size(); ++i) CHECK(obj.v[i] == mesh.vertices[i]);
  for (const auto& uv : obj.vt) {
    CHECK(uv.x() >= 0);
    CHECK(uv.x() <= 1);
    CHECK(uv.y() >= 0);
    CHECK(uv.y() <= 1);
  }
  // Every corner: its vertex, and bit for bit the coordinate contexts read there.
  std::set<std::pair<int, int>> vertexCharts;
  std::vector<std::vector<int>> vtOfVertexChart(mesh.vertices.size(), std::vector<int>(s->atlas().chartCount, -1));
  for (size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      REQUIRE(obj.f[f][k] == mesh.faces[f][k]);
      const int t = obj.ft[f][k];
      REQUIRE(t >= 0);
      REQUIRE(size_t(t) < obj.vt.size());
      Vec3 corner = Vec3::Zero();
      corner[k] = 1;
      CHECK(obj.vt[t] == s->texCoord({int(f), corner}));
      // Inside a chart a vertex's corners share one vt.
      const int chart = s->atlas().faceChart[f];
      int& shared = vtOfVertexChart[mesh.faces[f][k]][chart];
      if (shared < 0) shared = t;
      CHECK(shared == t);
      vertexCharts.insert({mesh.faces[f][k], chart});
    }
  // One vt per vertex and chart: a closed sphere has seams, so more vts than vertices.
  CHECK(s->atlas().chartCount > 1);
  CHECK(obj.vt.size() == vertexCharts.size());
  CHECK(obj.vt.size() > obj.v.size());
}

TEST_CASE("an image painted through the exported UVs is what the atlas paints", "[marching][export-uv]") {
  // Paint the faces inside a brush by hand, at their UV centroids in the exported OBJ, and
  // compare with the mask `fgsg atlas --paint` would write over the same atlas.
  const auto s = sphereSurface();
  const Obj obj = parseObj(texture::atlasUvObj(*s));
  const texture::Brush brush{Vec3(1, 0, 0), 0.6};
  const int size = 512;
  const texture::MaskImage mask = texture::paintMask(*s, size, {brush});
  int white = 0, black = 0;
  for (size_t f = 0; f < obj.f.size(); ++f) {
    double nearest = 1e9, farthest = 0;
    atlas::Vec2 centroid(0, 0);
    for (int k = 0; k < 3; ++k) {
      const double d = (obj.v[obj.f[f][k]] - brush.centre).norm();
      nearest = std::min(nearest, d);
      farthest = std::max(farthest, d);
      centroid += obj.vt[obj.ft[f][k]] / 3;
    }
    // Row 0 of the image is v = 1, as a paint program shows an OBJ's UVs.
    const int x = int(centroid.x() * size), row = size - 1 - int(centroid.y() * size);
    const uint8_t painted = mask.grey[size_t(row) * size + x];
    if (farthest < brush.radius - 0.15) {
      CHECK(int(painted) == 255);
      ++white;
    } else if (nearest > brush.radius + 0.15) {
      CHECK(int(painted) == 0);
      ++black;
    }
  }
  CHECK(white > 30);
  CHECK(black > 300);
}

TEST_CASE("the OBJ is written whole or not at all", "[marching][export-uv]") {
  const auto dir = fgsg::test::scratchDir("export_uv", "write");
  const auto s = sphereSurface();
  std::string error;
  REQUIRE(texture::writeAtlasUvObj(*s, (dir / "sphere.obj").string(), error));
  CHECK(fgsg::test::readFile(dir / "sphere.obj") == texture::atlasUvObj(*s));
  CHECK_FALSE(texture::writeAtlasUvObj(*s, (dir / "missing" / "sphere.obj").string(), error));
  CHECK_THAT(error, Catch::Contains((dir / "missing" / "sphere.obj").string()));
  CHECK_THAT(error, Catch::Contains("No such file or directory"));
  CHECK(fs::directory_iterator(dir) != fs::directory_iterator());
  size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  CHECK(files == 1);
}
