// Bricks up the vertical edges of a pier narrower than a brick (generators.h, "bricks":
// one brick per course along the left and the right face in turn): a brick along the
// narrow face is cut where that face ends, on every edge, whichever way the edge is
// stored. Kills the mutation "const bool left = (i == 0);" of tests/mutations/cells.txt
// (generators.cpp's sideFace ignoring EdgeSides::swapped), which survived the first
// mutation run (issue #51, docs/testing.md).
#include "tests/unit/cells/narrow_pier.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::cells;

TEST_CASE("bricks on a pier narrower than a brick end where its narrow faces end", "[cells]") {
  // The pier (narrow_pier.h): x in [0, 1], y in [0, 0.15], z in [0, 0.75] (10 courses of
  // 0.075), standing on the ground. Bricks 0.4 long and 0.1 deep: longer than the narrow
  // faces (0.15) with the corner's depth.
  const auto m = fgsg::test::narrowPierMesh();
  CellularTexture tex(m, buildFeatureMesh(m));
  fgsg::test::layPierBricks(tex);
  const FeatureMesh& fm = tex.features();

  // Of the four vertical edges, some are stored pointing down: sidesAt walks them upwards
  // and swaps their two faces (EdgeSides::swapped). The mutation matters on those only,
  // so the pier must have both kinds.
  int vertical = 0, swapped = 0;
  for (int e = 0; e < int(fm.edges.size()); ++e) {
    const FeatureEdge& edge = fm.edges[e];
    if (edge.direction != EdgeDirection::Vertical) continue;
    ++vertical;
    swapped += tex.sidesAt(e, 0.5 * edge.length).swapped;

    // Each course gets one brick (10), alternately along the wide face (±x: the whole
    // 0.4, from 0.1 outside the narrow face) and along the narrow one (±y): from 0.1
    // outside the wide face to the narrow face's far end, 0.1 + 0.15 = 0.25, cut there
    // because the face's free run ends there (reachInto).
    // Under the mutation a swapped edge asks reachInto about the other face, the wide one,
    // whose u axis (x) is across the brick's direction (y): "not along u", reach infinite,
    // so its narrow bricks are 0.4 long, reaching 0.15 past the pier (seen: y up to 0.3);
    // they then crowd out half the bricks of the edge beyond (5 of 10), and a swapped
    // edge whose narrow bricks meet an earlier edge's are cut by add's bisection instead,
    // 0.250001252 long, not the run's exact 0.25.
    int bricks = 0;
    for (const Cell& c : tex.cells()) {
      if (c.feature.kind != FeatureKind::Edge || c.feature.index != e) continue;
      ++bricks;
      const Vec3 along = c.axes.col(0);
      INFO("edge " << e << " brick at " << c.origin.transpose() << " along " << along.transpose());
      if (std::abs(along.x()) > 0.99) CHECK(c.size.x() == Approx(0.4).margin(1e-9));
      else {
        CHECK(std::abs(along.y()) > 0.99);
        CHECK(c.size.x() == Approx(0.25).margin(1e-9));
      }
    }
    INFO("edge " << e);
    CHECK(bricks == 10);
  }
  CHECK(vertical == 4);
  CHECK(swapped > 0);
  CHECK(swapped < vertical);

  // No cell reaches beyond the pier grown by the brick depth (the top's cells rise 0.1
  // above it; nothing goes below the ground).
  for (const Cell& c : tex.cells())
    for (const Vec3& p : c.corners()) {
      INFO("corner " << p.transpose());
      CHECK(p.x() >= -0.1 - 1e-9);
      CHECK(p.x() <= 1.1 + 1e-9);
      CHECK(p.y() >= -0.1 - 1e-9);
      CHECK(p.y() <= 0.25 + 1e-9);
      CHECK(p.z() >= -1e-9);
      CHECK(p.z() <= 0.85 + 1e-9);
    }
}
