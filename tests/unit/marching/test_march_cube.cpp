// Marching around the six-chart cube: every edge is a seam between charts turned against
// each other in the image, and a fold of 90 degrees in 3D.
#include "march_fixtures.h"

#include <cmath>
#include <random>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using namespace fgsg::rt::marching::testing;

namespace {

// On the loop y = y0 heading +x on the top side, the tangent at a point of the side with
// normal n: in the loop's plane, turning the way the loop goes.
Vec3 loopTangent(const Vec3& n) { return Vec3::UnitY().cross(n).normalized(); }

}  // namespace

TEST_CASE("a straight march around the cube comes back to its start", "[marching][march][cube]") {
  const ChartedMesh c = chartedCube(8, 1024);
  const auto s = prepared(c);
  const surface::SurfaceLocator locator(s->mesh());
  // The middle of the top side (a vertex of the 8 x 8 grid: the line runs on edges), and
  // a point off the grid.
  for (const Vec3& start : {Vec3(0, 0, 0.5), Vec3(0.0123, -0.0371, 0.5)}) {
    INFO("start " << start.transpose());
    const MarchPoint from = placeAt(*s, start, Vec3::UnitX());
    REQUIRE(from.chart == 0);
    // Sampled every 0.05 edges of surface length.
    MarchPoint p = from;
    int charts = 0, samples = 0;
    int lastChart = from.chart;
    double worstTurn = 0;
    while (charts < 4 || p.chart != 0 || s->position(p).x() < start.x() - 0.05) {
      MarchPoint next;
      MarchTrace trace;
      REQUIRE(s->march(p, 0.05, LengthUnit::Surface, next, &trace));
      REQUIRE(trace.adjacencyJumps == 0);
      REQUIRE(consistent(*s, next));
      const Vec3 a = s->position(p), b = s->position(next);
      // Consecutive samples the length apart, on the loop's plane, on the surface.
      REQUIRE(std::abs((b - a).norm() - 0.05) < 1e-9 * 0.05);
      REQUIRE(std::abs(b.y() - start.y()) < 1e-12);
      double distance = 1;
      locator.closestPoint(b, &distance);
      REQUIRE(distance < 1e-9);
      // The direction continues the loop (turned only by the fold it crossed).
      const Vec3 expected = loopTangent(s->mesh().faceNormals[next.at.face]);
      const double turn = std::acos(std::clamp(s->direction(next).dot(expected), -1.0, 1.0));
      worstTurn = std::max(worstTurn, turn);
      if (next.chart != lastChart) ++charts, lastChart = next.chart;
      p = next;
      REQUIRE(++samples < 200);
    }
    CHECK(worstTurn < kPi / 180);
    CHECK(charts == 4);
    CHECK(samples >= 4 * 19);  // a chord is at most its arc: at least 80 steps round 4 edges

    // An image-length march of four edges exactly (every side is 1 / 3 of the atlas
    // less the gutters): back at the start, heading the same way.
    const double edgeTexels = (1.0 / 3 - 8.0 / 1024) * 1024;
    MarchPoint back;
    MarchTrace trace;
    REQUIRE(s->march(from, 4 * edgeTexels, LengthUnit::Image, back, &trace));
    CHECK(trace.pointerJumps == 4);
    CHECK(trace.adjacencyJumps == 0);
    CHECK((s->position(back) - start).norm() < 1e-3);
    CHECK((s->position(back) - start).norm() < 1e-9);  // exact in fact
    CHECK(back.chart == 0);
    CHECK(s->direction(back).dot(Vec3::UnitX()) > std::cos(kPi / 180));
  }
}

TEST_CASE("a march across a cube edge keeps its angle with the edge", "[marching][march][cube]") {
  // Heading at an angle towards the +X side from the top: unfolded about the edge, the
  // path is a straight line, so on the +X side it runs down at the same angle to the edge.
  const auto s = prepared(chartedCube(8, 1024));
  const double edgeTexels = (1.0 / 3 - 8.0 / 1024) * 1024;  // texels per unit of length
  for (double degrees : {10.0, 35.0, 50.0, -30.0}) {  // all reach +X before +-Y
    INFO(degrees << " degrees");
    const double phi = degrees * kPi / 180;
    const Vec3 start(0.2, -0.1, 0.5), dir(std::cos(phi), std::sin(phi), 0);
    const double toEdge = (0.5 - start.x()) / std::cos(phi), more = 0.2;
    const Vec3 expected(0.5, start.y() + (toEdge + more) * std::sin(phi), 0.5 - more * std::cos(phi));
    MarchPoint to;
    MarchTrace trace;
    REQUIRE(s->march(placeAt(*s, start, dir), (toEdge + more) * edgeTexels, LengthUnit::Image, to, &trace));
    CHECK(trace.pointerJumps == 1);
    CHECK(to.chart == 2);
    CHECK((s->position(to) - expected).norm() < 1e-9);
    CHECK((s->direction(to) - Vec3(0, std::sin(phi), -std::cos(phi))).norm() < 1e-9);
    // The surface unit measures the chord: from the start to `expected`.
    REQUIRE(s->march(placeAt(*s, start, dir), (expected - start).norm(), LengthUnit::Surface, to));
    CHECK((s->position(to) - expected).norm() < 1e-9);
  }
}

TEST_CASE("an image position locates the exact surface point under it", "[marching][march][cube]") {
  const auto s = prepared(chartedCube(8, 512));
  const surface::SurfaceLocator locator(s->mesh());
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> coord(0, 512);
  int located = 0, refused = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec2 image(coord(rng), coord(rng));
    MarchPoint p;
    const int texel = s->image().texelAt(image);
    if (!s->locate(image, Vec2(0, 1), p)) {
      ++refused;
      // Outside every chart: a texel no chart covers, or a conservative one's outside.
      if (s->image().kind(texel) == TexelKind::Inner) CHECK((p.image - image).norm() < 1.5);
      continue;
    }
    ++located;
    REQUIRE(consistent(*s, p));
    REQUIRE((p.image - image).norm() < 1e-9);
    double distance = 1;
    locator.closestPoint(s->position(p), &distance);
    REQUIRE(distance < 1e-12);
    // Placing at the located point gives the same image position back.
    REQUIRE((s->place(p.at, s->direction(p)).image - image).norm() < 1e-9);
    // The texel's own point is its centre (the chart holds it) or the chart's point
    // nearest to it, inside the texel's square.
    const surface::SurfacePoint centre = s->texelPoint(texel);
    REQUIRE(centre.valid());
    const auto& uv = s->atlas().cornerUV[centre.face];
    const Vec2 at = (centre.bary[0] * uv[0] + centre.bary[1] * uv[1] + centre.bary[2] * uv[2]) * 512;
    REQUIRE((at - Vec2(texel % 512 + 0.5, texel / 512 + 0.5)).cwiseAbs().maxCoeff() <= 0.5 + 1e-9);
  }
  // Six charts of about 162 texels each side in 512^2: about 60 % covered.
  CHECK(located > 10000);
  CHECK(refused > 5000);
  CHECK_FALSE(s->texelPoint(0).valid());
  MarchPoint untouched;
  CHECK_FALSE(s->locate(Vec2(-1, 3), Vec2(1, 0), untouched));
  CHECK(untouched.at.face == -1);
}

TEST_CASE("a march heading out of a cube corner spins round it and stops after 4097 still pieces",
          "[marching][march][cube]") {
  // The corner (0.5, 0.5, 0.5) has three right angles round it. From the top side's two
  // triangles there (chart 0), heading out of the corner towards (1, 0.9) in x and y
  // (into no face, along no edge), the march turns round the corner and jumps between
  // its sides without moving; the 4097th piece in a row without progress (more than 4096)
  // ends it where it began, long before 2^22 faces.
  const auto s = prepared(chartedCube(8, 1024));
  const auto& mesh = s->mesh();
  const Vec3 corner(0.5, 0.5, 0.5);
  int starts = 0;
  for (int f = 0; f < int(mesh.faceCount()); ++f)
    for (int k = 0; k < 3; ++k) {
      if (s->atlas().faceChart[f] != 0 || (mesh.vertices[mesh.faces[f][k]] - corner).norm() > 0) continue;
      surface::SurfacePoint at;
      at.face = f;
      at.bary = Vec3::Zero();
      at.bary[k] = 1;
      const MarchPoint from = s->place(at, Vec3(1, 0.9, 0));
      for (LengthUnit unit : {LengthUnit::Surface, LengthUnit::Image}) {
        INFO("face " << f << (unit == LengthUnit::Surface ? ", surface length" : ", image length"));
        MarchPoint to;
        MarchTrace trace;
        CHECK_FALSE(s->march(from, unit == LengthUnit::Surface ? 0.1 : 3.0, unit, to, &trace));
        CHECK(trace.end == MarchEnd::NoProgress);
        CHECK(trace.pieces == 4097);
        CHECK((s->position(to) - corner).norm() <= 1e-15);
        ++starts;
      }
    }
  CHECK(starts == 2 * 2);  // the top side's two triangles at the corner, both units
}
