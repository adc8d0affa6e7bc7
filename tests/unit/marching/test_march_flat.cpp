// Marching on flat charts, where the exact answer is a straight line.
#include "march_fixtures.h"

#include <random>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using namespace fgsg::rt::marching::testing;

namespace {

// 3D length of one texel on flatSquare(20, 2.0, 1024, 4).
constexpr double kSquareTexel = 2.0 / (1024 - 8);

}  // namespace

TEST_CASE("on a flat chart a march is a straight segment of exactly its length", "[marching][march]") {
  const auto s = prepared(flatSquare(20, 2.0, 1024, 4));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-0.6, 0.6), angle(0, 2 * kPi), len(1e-6, 0.35);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 start(coord(rng), coord(rng), 0);
    const double phi = angle(rng), length = len(rng);
    const Vec3 dir(std::cos(phi), std::sin(phi), 0);
    const MarchPoint from = placeAt(*s, start, dir);
    REQUIRE((s->position(from) - start).norm() < 1e-12);
    REQUIRE((s->direction(from) - dir).norm() < 1e-12);

    MarchPoint to;
    REQUIRE(s->march(from, length, LengthUnit::Surface, to));
    REQUIRE(consistent(*s, to));
    REQUIRE((s->position(to) - (start + length * dir)).norm() < 1e-9 * length + 1e-12);
    REQUIRE(std::abs((s->position(to) - start).norm() - length) < 1e-9 * length);
    REQUIRE((s->direction(to) - dir).norm() < 1e-12);

    const double texels = length / kSquareTexel;
    REQUIRE(s->march(from, texels, LengthUnit::Image, to));
    REQUIRE(consistent(*s, to));
    REQUIRE((s->position(to) - (start + length * dir)).norm() < 1e-9 * length + 1e-12);
    REQUIRE((to.image - from.image).norm() == Approx(texels).epsilon(1e-9));
  }
}

TEST_CASE("a march off an open chart stops on its border with false", "[marching][march]") {
  const auto s = prepared(flatSquare(20, 2.0, 1024, 4));
  for (double degrees : {0.0, 30.0, -41.0}) {
    const double phi = degrees * kPi / 180;
    const Vec3 start(0.1, 0.05, 0), dir(std::cos(phi), std::sin(phi), 0);
    for (LengthUnit unit : {LengthUnit::Surface, LengthUnit::Image}) {
      MarchPoint to;
      MarchTrace trace;
      CHECK_FALSE(s->march(placeAt(*s, start, dir), 5000, unit, to, &trace));
      CHECK(consistent(*s, to));
      // The border x = 1, where the straight line meets it.
      const double run = (1 - start.x()) / std::cos(phi);
      CHECK((s->position(to) - (start + run * dir)).norm() < 1e-12);
      CHECK(trace.pointerJumps == 0);
      CHECK(trace.adjacencyJumps == 0);
    }
  }
}

TEST_CASE("a march along the mesh's own edges is exact and never spins", "[marching][march]") {
  // From a grid vertex along a grid line, and along the squares' diagonals: the line
  // runs on edges and through vertices all the way.
  const auto s = prepared(flatSquare(20, 2.0, 1024, 4));
  const double cell = 2.0 / 19;
  const Vec3 vertex(-1 + 9 * cell, -1 + 9 * cell, 0);
  for (const Vec3& dir : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(1, 1, 0).normalized(), Vec3(-1, -1, 0).normalized()}) {
    MarchPoint to;
    MarchTrace trace;
    REQUIRE(s->march(placeAt(*s, vertex, dir), 0.9, LengthUnit::Surface, to, &trace));
    CHECK((s->position(to) - (vertex + 0.9 * dir)).norm() < 1e-12);
    CHECK(trace.pieces < 100);
  }
}

TEST_CASE("a long image-length march settles on the coarse levels with the same answer", "[marching][march]") {
  const auto s = prepared(flatSquare(20, 2.0, 1024, 4));
  const Vec3 start(-0.7, -0.5, 0), dir = Vec3(3, 2, 0).normalized();
  const MarchPoint from = placeAt(*s, start, dir);
  MarchPoint once, stepped = from;
  MarchTrace trace;
  REQUIRE(s->march(from, 600, LengthUnit::Image, once, &trace));
  CHECK(trace.coarse);
  for (int k = 0; k < 100; ++k) {
    REQUIRE(s->march(stepped, 6, LengthUnit::Image, stepped, &trace));
    REQUIRE_FALSE(trace.coarse);  // too short to look
  }
  CHECK((s->position(once) - s->position(stepped)).norm() < 1e-12);
  CHECK((s->position(once) - (start + 600 * kSquareTexel * dir)).norm() < 1e-12);
}

TEST_CASE("a march crosses a seam between two flat charts without a kink", "[marching][march]") {
  // The charts' images lie a one-texel gutter apart (both charts' pointers in one
  // column) or a wide one. They are squeezed along x, so image and 3D directions
  // differ; in 3D the line must run on straight through the seam.
  for (double gap : {1.5, 6.0}) {
    const auto s = prepared(splitSquare(gap));
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> y(-0.8, 0.8), angle(-0.85, 0.85);  // all reach x > 0
    for (int k = 0; k < 200; ++k) {
      const double phi = angle(rng);
      const Vec3 start(-0.6, y(rng), 0), dir(std::cos(phi), std::sin(phi), 0);
      const double length = 1.1;
      if (std::abs(start.y() + length * dir.y()) > 0.95) continue;
      MarchPoint to;
      MarchTrace trace;
      INFO("gap " << gap << " start " << start.transpose() << " angle " << phi);
      REQUIRE(s->march(placeAt(*s, start, dir), length, LengthUnit::Surface, to, &trace));
      CHECK(trace.pointerJumps == 1);
      CHECK(trace.adjacencyJumps == 0);
      CHECK(to.chart == 1);
      CHECK((s->position(to) - (start + length * dir)).norm() < 1e-9);
      CHECK((s->direction(to) - dir).norm() < 1e-9);
    }
  }
}

TEST_CASE("degenerate requests are answered without marching", "[marching][march]") {
  const auto s = prepared(flatSquare(20, 2.0, 256, 4));
  const MarchPoint from = placeAt(*s, Vec3(0.2, 0.3, 0), Vec3(1, 0, 0));
  MarchPoint to;
  CHECK(s->march(from, 0.0, LengthUnit::Surface, to));
  CHECK((s->position(to) - s->position(from)).norm() == 0);
  CHECK(s->march(from, -1.0, LengthUnit::Image, to));
  CHECK((s->position(to) - s->position(from)).norm() == 0);
  CHECK_FALSE(s->march(from, std::nan(""), LengthUnit::Surface, to));
  CHECK_FALSE(s->march(from, INFINITY, LengthUnit::Surface, to));
  MarchPoint still = from;
  still.dir = Vec2::Zero();
  CHECK_FALSE(s->march(still, 0.1, LengthUnit::Surface, to));
  MarchPoint nowhere;
  CHECK_FALSE(s->march(nowhere, 0.1, LengthUnit::Surface, to));
  // A direction along the normal heads along the face's first edge, in the plane.
  const MarchPoint up = placeAt(*s, Vec3(0.2, 0.3, 0), Vec3(0, 0, 1));
  CHECK(std::abs(s->direction(up).z()) < 1e-12);
  CHECK(s->direction(up).norm() == Approx(1.0));
}

TEST_CASE("texture coordinates come from the mesh when it has them, else from the atlas", "[marching][march]") {
  ChartedMesh c = flatSquare(5, 2.0, 64, 4);
  auto s = prepared(c);
  surface::SurfacePoint p{3, Vec3(0.2, 0.3, 0.5)};
  const auto& uv = c.atlas.cornerUV[3];
  CHECK((s->texCoord(p) - (0.2 * uv[0] + 0.3 * uv[1] + 0.5 * uv[2])).norm() < 1e-15);
  c.mesh.textureUV.assign(c.mesh.faceCount(), {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)});
  s = prepared(c);
  CHECK((s->texCoord(p) - Vec2(0.3, 0.5)).norm() < 1e-15);
}
