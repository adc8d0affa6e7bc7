#include "charted_shapes.h"

#include "runtime/marching/geometry_image.h"
#include "runtime/marching/image_triangles.h"

#include <catch2/catch.hpp>

#include <random>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using namespace fgsg::rt::marching::testing;

namespace {

GeometryImage imageOf(const ChartedMesh& c, std::vector<ImageTriangle>* trianglesOut = nullptr) {
  std::vector<ImageTriangle> triangles;
  std::string error;
  REQUIRE(buildImageTriangles(c.mesh, c.atlas, triangles, error));
  GeometryImage img = GeometryImage::build(c.mesh, triangles, c.atlas.resolution);
  if (trianglesOut) *trianglesOut = std::move(triangles);
  return img;
}

}  // namespace

TEST_CASE("a square chart on texel lines covers exactly the texels whose centres it holds", "[marching][image]") {
  // Margin 4 of 256: the chart spans [4, 252] in image units.
  const ChartedMesh c = flatSquare(20, 2.0, 256, 4);
  const GeometryImage img = imageOf(c);
  CHECK(img.stats().innerTexels == 248u * 248u);
  CHECK(img.stats().conservativeTexels == 0u);
  CHECK(img.stats().indirectionTexels == 250u * 250u - 248u * 248u);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const int t = img.index(x, y);
      const bool inner = x >= 4 && x < 252 && y >= 4 && y < 252;
      const bool ring = !inner && x >= 3 && x < 253 && y >= 3 && y < 253;
      REQUIRE(img.kind(t) == (inner ? TexelKind::Inner : ring ? TexelKind::Indirection : TexelKind::Background));
      REQUIRE(img.pointers(t).size() == (ring ? 1u : 0u));
      if (ring) {
        // An open square: nothing continues it.
        CHECK(img.pointers(t)[0].chart == 0);
        CHECK(img.pointers(t)[0].target == -1);
      }
    }
  CHECK(img.stats().boundaryPointers == img.stats().pointers);
}

TEST_CASE("a chart off the texel lines claims the texels it overlaps conservatively", "[marching][image]") {
  // Margin 4.7: the chart spans [4.7, 251.3]; centres inside: 5..250; overlapped: 4..251.
  const ChartedMesh c = flatSquare(20, 2.0, 256, 4.7);
  const GeometryImage img = imageOf(c);
  CHECK(img.stats().innerTexels == 248u * 248u);
  CHECK(img.stats().conservativeTexels == 248u * 248u - 246u * 246u);
  // A conservative texel's point is the chart's closest point to its centre: on the border.
  const int corner = img.index(4, 4);
  REQUIRE(img.kind(corner) == TexelKind::Inner);
  const double side = 2.0, scale = side / (256 - 2 * 4.7);  // 3D units per texel
  CHECK(img.position(corner).x() == Approx(-1.0).margin(1e-6));
  CHECK(img.position(corner).y() == Approx(-1.0).margin(1e-6));
  const int inside = img.index(10, 20);
  CHECK(img.position(inside).x() == Approx(-1.0 + (10.5 - 4.7) * scale).margin(1e-6));
  CHECK(img.position(inside).y() == Approx(-1.0 + (20.5 - 4.7) * scale).margin(1e-6));
}

TEST_CASE("on the cube every indirection texel points across an edge to a border texel of another side",
          "[marching][image]") {
  const ChartedMesh c = chartedCube(8, 512);
  std::vector<ImageTriangle> triangles;
  const GeometryImage img = imageOf(c, &triangles);
  REQUIRE(img.stats().pointers > 0);
  CHECK(img.stats().boundaryPointers == 0u);
  const double texel = triangles[0].texelLength;  // the same on every side
  const int n = img.size();
  size_t checked = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int t = img.index(x, y);
      for (const IndirectionPointer& p : img.pointers(t)) {
        REQUIRE(p.target >= 0);
        CHECK(img.chart(p.target) != p.chart);
        // The mean of the chart's texels around, as §4 defines the pointer's 3D point.
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        int around = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= n || ny >= n || img.chart(img.index(nx, ny)) != p.chart) continue;
            mean += img.position(img.index(nx, ny)).cast<double>();
            ++around;
          }
        mean /= around;
        const Eigen::Vector3d target = img.position(p.target).cast<double>();
        CHECK((target - mean).norm() <= 2 * kSeamReachTexels * texel);
        // Both lie next to a cube edge: two coordinates within about a texel of +-0.5.
        int onFaces = 0;
        for (int d = 0; d < 3; ++d) onFaces += std::abs(std::abs(target[d]) - 0.5) < 1.5 * texel;
        CHECK(onFaces >= 2);
        ++checked;
      }
    }
  CHECK(checked == img.stats().pointers);
}

TEST_CASE("inner texels hold the exact surface point at their centre", "[marching][image]") {
  const ChartedMesh c = chartedCube(8, 256);
  std::vector<ImageTriangle> triangles;
  const GeometryImage img = imageOf(c, &triangles);
  for (int t = 0; t < img.size() * img.size(); ++t) {
    if (img.kind(t) != TexelKind::Inner) continue;
    const int f = img.face(t);
    REQUIRE(f >= 0);
    CHECK(img.chart(t) == c.atlas.faceChart[f]);
    const Vec3 b = triangles[f].closestBary(Vec2(t % img.size() + 0.5, t / img.size() + 0.5));
    const auto& v = c.mesh.faces[f];
    const Vec3 exact = b[0] * c.mesh.vertices[v[0]] + b[1] * c.mesh.vertices[v[1]] + b[2] * c.mesh.vertices[v[2]];
    REQUIRE((img.position(t).cast<double>() - exact).norm() < 1e-6);
    REQUIRE(exact.cwiseAbs().maxCoeff() == Approx(0.5).margin(1e-12));
  }
}

TEST_CASE("a texel between two charts one texel apart holds a pointer for each", "[marching][image]") {
  // The halves' images are 1.5 texels apart (0.9 x 1.5 after the squeeze): one column
  // of background texels between them, next to both.
  const ChartedMesh c = splitSquare(1.5);
  const GeometryImage img = imageOf(c);
  size_t shared = 0;
  for (int t = 0; t < img.size() * img.size(); ++t) {
    const auto pointers = img.pointers(t);
    if (pointers.size() < 2) continue;
    REQUIRE(pointers.size() == 2u);
    CHECK(pointers[0].chart == 0);
    CHECK(pointers[1].chart == 1);
    // Each continues into the other half.
    REQUIRE(pointers[0].target >= 0);
    REQUIRE(pointers[1].target >= 0);
    CHECK(img.chart(pointers[0].target) == 1);
    CHECK(img.chart(pointers[1].target) == 0);
    ++shared;
  }
  CHECK(shared >= 200u);  // the column along the split, about 0.9 x 240 texels tall
}

TEST_CASE("coarse levels record the cells wholly inside one chart", "[marching][image]") {
  const ChartedMesh c = chartedCube(8, 256);
  const GeometryImage img = imageOf(c);
  REQUIRE(img.levelCount() == 9);  // 256 .. 1
  for (int level = 1; level < img.levelCount(); ++level) {
    const int s = img.levelSize(level), span = 1 << level;
    for (int cy = 0; cy < s; ++cy)
      for (int cx = 0; cx < s; ++cx) {
        int value = img.chart(img.index(cx * span, cy * span));
        bool any = false;
        for (int y = cy * span; y < std::min(img.size(), (cy + 1) * span); ++y)
          for (int x = cx * span; x < std::min(img.size(), (cx + 1) * span); ++x) {
            const int chart = img.chart(img.index(x, y));
            any |= chart >= 0;
            if (chart != value) value = GeometryImage::kMixedCell;
          }
        if (value == GeometryImage::kMixedCell && !any) value = GeometryImage::kEmptyCell;
        REQUIRE(img.cell(level, cx, cy) == value);
      }
  }
}

TEST_CASE("a segment is in a chart exactly when every texel it crosses is", "[marching][image]") {
  const ChartedMesh c = chartedCube(8, 256);
  const GeometryImage img = imageOf(c);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(0.0, 256.0), len(0.0, 120.0), angle(0, 2 * kPi);
  int inside = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec2 a(coord(rng), coord(rng));
    const double l = len(rng), phi = angle(rng);
    const Vec2 b = a + l * Vec2(std::cos(phi), std::sin(phi));
    if (b.minCoeff() < 0 || b.maxCoeff() >= 256) continue;
    const int chart = img.chart(img.texelAt(a));
    if (chart < 0) continue;
    // Every texel whose square the segment enters (slab test against each square).
    bool all = true;
    for (int y = int(std::min(a.y(), b.y())); y <= int(std::max(a.y(), b.y())) && all; ++y)
      for (int x = int(std::min(a.x(), b.x())); x <= int(std::max(a.x(), b.x())); ++x) {
        double t0 = 0, t1 = 1;
        for (int d = 0; d < 2; ++d) {
          const double lo = d == 0 ? x : y, dir = b[d] - a[d];
          if (dir == 0) {
            if (a[d] < lo || a[d] > lo + 1) t0 = 2;
            continue;
          }
          double e0 = (lo - a[d]) / dir, e1 = (lo + 1 - a[d]) / dir;
          if (e0 > e1) std::swap(e0, e1);
          t0 = std::max(t0, e0);
          t1 = std::min(t1, e1);
        }
        if (t0 < t1 && img.chart(img.index(x, y)) != chart) {
          all = false;
          break;
        }
      }
    INFO("segment " << a.transpose() << " -> " << b.transpose());
    REQUIRE(img.segmentInChart(a, b, chart) == all);
    inside += all;
  }
  CHECK(inside > 300);  // both answers were exercised
}

TEST_CASE("an image restored from its texels is the image built", "[marching][image]") {
  const ChartedMesh c = chartedCube(4, 128);
  std::vector<ImageTriangle> triangles;
  const GeometryImage built = imageOf(c, &triangles);
  GeometryImage restored;
  std::string error;
  REQUIRE(GeometryImage::restore(c.mesh, triangles, built.texels(), restored, error));
  CHECK(restored.stats().pointers == built.stats().pointers);
  for (int t = 0; t < built.size() * built.size(); ++t) {
    REQUIRE(restored.position(t) == built.position(t));
    REQUIRE(restored.chart(t) == built.chart(t));
  }
  for (int level = 1; level < built.levelCount(); ++level)
    REQUIRE(restored.cell(level, 0, 0) == built.cell(level, 0, 0));

  SECTION("an inner texel without a face is refused") {
    GeometryImage::Texels bad = built.texels();
    const int t = built.index(64, 32);
    REQUIRE(bad.kind[t] == uint8_t(TexelKind::Inner));
    bad.face[t] = -1;
    CHECK_FALSE(GeometryImage::restore(c.mesh, triangles, bad, restored, error));
  }
  SECTION("a pointer for a chart the texel does not border is refused") {
    GeometryImage::Texels bad = built.texels();
    bad.pointers[0].chart = (bad.pointers[0].chart + 1) % 6;
    CHECK_FALSE(GeometryImage::restore(c.mesh, triangles, bad, restored, error));
  }
  SECTION("a pointer to a background texel is refused") {
    GeometryImage::Texels bad = built.texels();
    bad.pointers[0].target = 0;  // the image's corner: background
    CHECK_FALSE(GeometryImage::restore(c.mesh, triangles, bad, restored, error));
  }
  SECTION("a background texel next to a chart without pointers is refused") {
    GeometryImage::Texels bad = built.texels();
    int t = 0;
    while (bad.kind[t] != uint8_t(TexelKind::Indirection)) ++t;
    bad.kind[t] = uint8_t(TexelKind::Background);
    CHECK_FALSE(GeometryImage::restore(c.mesh, triangles, bad, restored, error));
  }
}

TEST_CASE("building is deterministic across threads", "[marching][image]") {
  const ChartedMesh c = chartedCube(16, 512);
  const GeometryImage a = imageOf(c), b = imageOf(c);
  CHECK(a.texels().kind == b.texels().kind);
  CHECK(a.texels().face == b.texels().face);
  REQUIRE(a.texels().pointers.size() == b.texels().pointers.size());
  for (size_t i = 0; i < a.texels().pointers.size(); ++i) {
    REQUIRE(a.texels().pointers[i].chart == b.texels().pointers[i].chart);
    REQUIRE(a.texels().pointers[i].target == b.texels().pointers[i].target);
  }
}

TEST_CASE("atlases that do not fit the mesh are refused with the face named", "[marching][image]") {
  ChartedMesh c = chartedCube(2, 64);
  std::vector<ImageTriangle> triangles;
  std::string error;
  SECTION("mirrored") {
    std::swap(c.atlas.cornerUV[5][1], c.atlas.cornerUV[5][2]);
    CHECK_FALSE(buildImageTriangles(c.mesh, c.atlas, triangles, error));
    CHECK(error == "face 5 is mirrored in the atlas (clockwise, the surface is counter-clockwise)");
  }
  SECTION("degenerate") {
    c.atlas.cornerUV[3][2] = c.atlas.cornerUV[3][1];
    CHECK_FALSE(buildImageTriangles(c.mesh, c.atlas, triangles, error));
    CHECK(error == "face 3 is degenerate in the atlas (zero area)");
  }
  SECTION("outside the unit square") {
    c.atlas.cornerUV[7][0].x() = 1.5;
    CHECK_FALSE(buildImageTriangles(c.mesh, c.atlas, triangles, error));
    CHECK(error == "face 7 has texture coordinates outside the unit square");
  }
  SECTION("chart out of range") {
    c.atlas.faceChart[2] = 6;
    CHECK_FALSE(buildImageTriangles(c.mesh, c.atlas, triangles, error));
    CHECK(error == "face 2 has chart 6, not one of the atlas's 6");
  }
  SECTION("wrong face count") {
    c.atlas.faceChart.pop_back();
    CHECK_FALSE(buildImageTriangles(c.mesh, c.atlas, triangles, error));
    CHECK(error == "the atlas has 47 faces, the surface 48");
  }
}
