// atlasFromTextureUV: the file's own charts, validated (finite, not degenerate, not
// mirrored, not overlapping, each error naming the faces) and re-packed by a common scale
// and a move per chart, never turned or mirrored.
#include "runtime/atlas/atlas.h"
#include "runtime/surface/procedural.h"

#include "atlas_checks.h"

#include <catch2/catch.hpp>

using namespace fgsg::rt;
using atlas::Vec2;
using fgsg::test::checkAtlas;
using fgsg::test::loadTestMesh;

namespace {

// A flat grid of 2 x 1 squares (four triangles): faces 0, 1 on the left square, 2, 3 on
// the right one. Texture coordinates: each square its own chart, placed as given.
surface::SurfaceMesh twoSquares(const Vec2& leftAt, const Vec2& rightAt) {
  surface::SurfaceMesh m;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) m.vertices.emplace_back(x, y, 0);
  // Vertices: 0 1 2 on y = 0, 3 4 5 on y = 1.
  m.faces = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  auto square = [](const Vec2& at) {
    return std::array<std::array<Vec2, 3>, 2>{
        {{at, at + Vec2(0.25, 0), at + Vec2(0.25, 0.25)}, {at, at + Vec2(0.25, 0.25), at + Vec2(0, 0.25)}}};
  };
  const auto l = square(leftAt), r = square(rightAt);
  m.textureUV = {l[0], l[1], r[0], r[1]};
  m.buildTopology();
  return m;
}

std::string failure(const surface::SurfaceMesh& mesh) {
  atlas::Atlas a;
  std::string error;
  REQUIRE_FALSE(atlas::atlasFromTextureUV(mesh, {}, a, error));
  REQUIRE(a.chartCount == 0);
  return error;
}

}  // namespace

TEST_CASE("texture charts are re-packed by one scale and a move each", "[texture atlas]") {
  const surface::SurfaceMesh mesh = twoSquares(Vec2(0, 0), Vec2(0.5, 0.5));
  atlas::Atlas a;
  std::string error;
  REQUIRE(atlas::atlasFromTextureUV(mesh, {}, a, error));
  REQUIRE(a.chartCount == 2);
  REQUIRE(a.faceChart == std::vector<int>{0, 0, 1, 1});
  checkAtlas(mesh, a, 2);
  // Each corner is scale * file UV + the chart's offset: the same scale everywhere, no
  // turn, no mirror.
  const double scale = (a.cornerUV[0][1] - a.cornerUV[0][0]).x() / 0.25;
  REQUIRE(scale > 0);
  for (int f = 0; f < 4; ++f) {
    const Vec2 offset = a.cornerUV[f][0] - scale * mesh.textureUV[f][0];
    const Vec2 chartOffset = a.cornerUV[f < 2 ? 0 : 2][0] - scale * mesh.textureUV[f < 2 ? 0 : 2][0];
    for (int k = 0; k < 3; ++k) {
      const Vec2 expected = scale * mesh.textureUV[f][k] + offset;
      REQUIRE((a.cornerUV[f][k] - expected).norm() < 1e-12);
    }
    REQUIRE((offset - chartOffset).norm() < 1e-12);
  }
}

TEST_CASE("a generated atlas read back as texture coordinates keeps its charts and layout", "[texture atlas]") {
  surface::SurfaceMesh mesh = loadTestMesh("elephant.off");
  atlas::Atlas generated;
  std::string error;
  REQUIRE(atlas::buildAtlas(mesh, {}, generated, error));
  mesh.textureUV = generated.cornerUV;
  atlas::AtlasOptions options;
  options.gutterTexels = 3;  // a different gutter: the charts must move
  atlas::Atlas a;
  INFO(error);
  REQUIRE(atlas::atlasFromTextureUV(mesh, options, a, error));
  REQUIRE(a.chartCount == generated.chartCount);
  REQUIRE(a.faceChart == generated.faceChart);  // both number charts by their lowest face
  checkAtlas(mesh, a, 3);
  // One scale for all charts: the ratio of corresponding edge lengths.
  const double scale = (a.cornerUV[0][1] - a.cornerUV[0][0]).norm() /
                       (generated.cornerUV[0][1] - generated.cornerUV[0][0]).norm();
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec2 was = generated.cornerUV[f][(k + 1) % 3] - generated.cornerUV[f][k];
      const Vec2 is = a.cornerUV[f][(k + 1) % 3] - a.cornerUV[f][k];
      REQUIRE((is - scale * was).norm() < 1e-12);
    }
}

TEST_CASE("overlapping texture coordinates name both faces", "[texture atlas]") {
  // The right square's chart lies half over the left one's.
  const surface::SurfaceMesh mesh = twoSquares(Vec2(0, 0), Vec2(0.125, 0));
  REQUIRE(failure(mesh) ==
          "texture coordinates overlap: faces 0 and 2 cover the same place in UV space (near (0.229167, 0.0833333))");
}

TEST_CASE("charts that only touch do not overlap", "[texture atlas]") {
  // The right square laid left of the left one: their outer edges touch along u = 0.
  const surface::SurfaceMesh mesh = twoSquares(Vec2(0, 0), Vec2(-0.25, 0));
  atlas::Atlas a;
  std::string error;
  INFO(error);
  REQUIRE(atlas::atlasFromTextureUV(mesh, {}, a, error));
  REQUIRE(a.chartCount == 2);
  checkAtlas(mesh, a, 2);
}

TEST_CASE("a mirrored texture triangle is named", "[texture atlas]") {
  surface::SurfaceMesh mesh = twoSquares(Vec2(0, 0), Vec2(0.5, 0.5));
  // Face 3's third corner moved across its first edge: the triangle runs clockwise while
  // staying in its chart (the edge it shares with face 2 keeps its coordinates), and
  // covers less than face 2, so face 3 is the one against the chart.
  mesh.textureUV[3][2] = Vec2(0.625, 0.5);
  REQUIRE(failure(mesh) ==
          "texture coordinates are mirrored at face 3: each runs against the rest of its chart (a "
          "flipped triangle in UV space)");
}

TEST_CASE("a chart mirrored as a whole is refused", "[texture atlas]") {
  surface::SurfaceMesh mesh = twoSquares(Vec2(0, 0), Vec2(0.5, 0.5));
  for (int f : {2, 3})
    for (Vec2& p : mesh.textureUV[f]) p.x() = 2.0 - p.x();
  REQUIRE(failure(mesh) ==
          "texture coordinates are mirrored: 1 of 2 charts run clockwise in UV space (the charts of "
          "face 2); marching cannot turn directions across a mirrored chart, so mirror the UV layout "
          "(or the faces) in a modelling tool");
}

TEST_CASE("degenerate and non-finite texture coordinates are named", "[texture atlas]") {
  surface::SurfaceMesh mesh = twoSquares(Vec2(0, 0), Vec2(0.5, 0.5));
  mesh.textureUV[1][2] = mesh.textureUV[1][0];
  REQUIRE(failure(mesh) ==
          "texture coordinates are degenerate (a triangle without area in UV space) at face 1: the "
          "surface there cannot be told apart in a texture");
  mesh = twoSquares(Vec2(0, 0), Vec2(0.5, 0.5));
  mesh.textureUV[2][1].y() = NAN;
  REQUIRE(failure(mesh) == "texture coordinates are not finite numbers (or beyond +-1e9) at face 2 (first: (0.75, nan))");
  mesh = twoSquares(Vec2(0, 0), Vec2(0.5, 0.5));
  mesh.textureUV[0][0].x() = mesh.textureUV[1][0].x() = -1e300;
  REQUIRE(failure(mesh) ==
          "texture coordinates are not finite numbers (or beyond +-1e9) at faces 0 and 1 (first: (-1e+300, 0))");
}

TEST_CASE("a surface without texture coordinates has no texture atlas", "[texture atlas]") {
  surface::SurfaceMesh mesh = surface::plane(1, 1, 2);
  REQUIRE(failure(mesh) == "texture coordinates: the surface has none");
}
