// Occupancy maps and the mortar surface where the stepped column does not reach: an
// interval inside another, a cylinder's face across its seam, a needle-sharp vertex.
// Each case was a surviving mutation of the mutation run (issue #51, docs/testing.md).
#include "runtime/cells/feature_mesh.h"
#include "runtime/cells/mortar.h"
#include "runtime/cells/occupancy.h"
#include "runtime/surface/procedural.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace fgsg::rt;
using namespace fgsg::rt::cells;

TEST_CASE("an interval added inside another leaves the union as it was", "[cells]") {
  IntervalSet s;
  s.add(0, 10);
  s.add(2, 4);
  REQUIRE(s.intervals().size() == 1);
  CHECK(s.intervals()[0].lo == 0);
  CHECK(s.intervals()[0].hi == 10);
  const auto g = s.gaps(0, 12);
  REQUIRE(g.size() == 1);
  CHECK(g[0].lo == 10);
  CHECK(g[0].hi == 12);
}

TEST_CASE("an open cylinder's face map is one band of the full circumference across its seam", "[cells]") {
  // 48 segments: a vertex at angle pi, the seam of the face's parameter space (angles in
  // [-pi, pi)), so the triangles beside it must be unwrapped to stay one band.
  const double r = 1.5, h = 2;
  const surface::SurfaceMesh m = surface::cylinder(r, h, 48);
  const FeatureMesh fm = buildFeatureMesh(m);
  REQUIRE(fm.faces.size() == 1);
  REQUIRE(fm.faces[0].kind == FaceKind::Cylindrical);
  const FaceOccupancy map(fm.faces[0], m);
  CHECK(map.hi().x() - map.lo().x() == Approx(2 * std::numbers::pi * r).margin(1e-9));
  const auto runs = map.insideRuns(0.5, 1.5);
  REQUIRE(runs.size() == 1);
  CHECK(runs[0].length() == Approx(2 * std::numbers::pi * r).margin(1e-9));
}

TEST_CASE("mortar moves a needle-sharp vertex three offsets at most", "[cells]") {
  // A closed pyramid on a 0.2 x 0.2 square, 10 high: the planes around its apex are all
  // nearly vertical, so their least-squares offset point lies far out (about 50 offsets);
  // the apex is moved exactly three offsets, the base corners by their own planes.
  surface::SurfaceMesh m;
  m.vertices = {{-0.1, -0.1, 0}, {0.1, -0.1, 0}, {0.1, 0.1, 0}, {-0.1, 0.1, 0}, {0, 0, 10}};
  m.faces = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 2, 1}, {0, 3, 2}};
  m.buildTopology();
  const double offset = 0.01;
  const Mesh mortar = mortarMesh(m, offset);
  REQUIRE(mortar.positions.size() == 9 * m.faces.size());
  double apexMove = 0, largest = 0;
  for (size_t f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = m.faces[f][k];
      const Vec3 p(mortar.positions[9 * f + 3 * k], mortar.positions[9 * f + 3 * k + 1],
                   mortar.positions[9 * f + 3 * k + 2]);
      const double move = (p - m.vertices[v]).norm();
      largest = std::max(largest, move);
      if (v == 4) apexMove = move;
    }
  CHECK(apexMove == Approx(3 * offset).margin(2e-6));  // floats of about 10: 1e-6 apart
  CHECK(largest <= 3 * offset + 2e-6);
}
