// Bricks up the vertical edges of a leaning pier (issue #51, docs/testing.md on
// generators.cpp's reachInto): the narrow pier of narrow_pier.h sheared so that its axis
// leans 5 or 9 degrees from up (within the 10 degrees that still make its long edges
// vertical), within the plane of its narrow faces or of its wide ones. Each vertical
// edge lays one brick per course, alternately along either face, as on the upright pier;
// a brick along a face whose course bounds are not square to the edge is a parallelogram
// with a level top and bottom (the faces' courses are level), cut where the face's free
// run along the brick's own direction ends.
//
// Before the fix reachInto read the face's free run along the face's u axis, level, from
// the brick's bottom corner, and trusted it only where the brick's direction was within
// 8.1 degrees of u (|away . u| >= 0.99). Leaning 9 degrees in the narrow faces' plane,
// the bricks along the narrow faces (their direction 9 degrees off level) got an infinite
// reach: 0.4 long, 0.15 past the pier, crowding out two edges (0 and 1 bricks instead
// of 10). Leaning 5 degrees, the run's start (the edge at the course's top, where the
// strip's run starts) missed the bottom corner by 0.075 tan 5 = 0.0066, so the reach was
// 0 and the bricks were cut to the corner's 0.1 (two edges; the other two got 0.2434).
// Leaning 5 degrees in the wide faces' plane, the same for the bricks along the wide
// faces (0.1 instead of 0.4); at 9 degrees those were 0.4 long but square boxes on a
// leaning edge: their bottoms dropped 0.3 sin 9 = 0.047 below the ground and their far
// ends missed the course lines.
#include "tests/unit/cells/narrow_pier.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::cells;
using fgsg::test::NarrowPier;
using fgsg::test::PierLean;

namespace {

constexpr double kPierDegree = 3.14159265358979323846 / 180;

// How far p lies outside the pier's layer of cells: the pier grown by the brick depth
// on its four sides and its top (the largest signed distance past those five planes;
// <= 0 inside). The ground is checked apart.
double pastLeaningPierLayer(const Vec3& p, double leanDegrees, PierLean lean) {
  const double t = std::tan(leanDegrees * kPierDegree), cosLean = 1 / std::sqrt(1 + t * t);
  const int sheared = lean == PierLean::InNarrowFaces ? 1 : 0;  // y (or x) += z tan
  const double d = NarrowPier::kDepth;
  double out = p.z() - NarrowPier::kHeight - d;
  for (int a : {0, 1}) {
    // A sheared side's plane q = const has the unit normal (e_a - t e_z) cos(lean).
    const double q = a == sheared ? p[a] - t * p.z() : p[a], scale = a == sheared ? cosLean : 1;
    const double size = a == 0 ? NarrowPier::kLength : NarrowPier::kWidth;
    out = std::max({out, -q * scale - d, (q - size) * scale - d});
  }
  return out;
}

}  // namespace

TEST_CASE("bricks on a leaning pier are level and cut where its narrow faces end", "[cells]") {
  const double d = NarrowPier::kDepth, course = NarrowPier::kCourse;
  for (PierLean lean : {PierLean::InNarrowFaces, PierLean::InWideFaces})
    for (double degrees : {0.0, 5.0, 9.0}) {
      const bool inNarrow = lean == PierLean::InNarrowFaces;
      const double cosLean = std::cos(degrees * kPierDegree), sinLean = std::sin(degrees * kPierDegree);
      INFO("leaning " << degrees << " degrees in the " << (inNarrow ? "narrow" : "wide") << " faces' plane");
      const auto m = fgsg::test::narrowPierMesh(degrees, lean);
      CellularTexture tex(m, buildFeatureMesh(m));
      fgsg::test::layPierBricks(tex);
      const FeatureMesh& fm = tex.features();

      // The faces at each vertical edge stay square to each other (the shear is within
      // one face's plane), so the corner's region is d x d and a brick starts d outside
      // the other face, as on the upright pier. Along the wide faces (direction +-x, or
      // tilted by the lean in the wide faces' plane): the whole 0.4 (the face is 1 wide).
      // Along the narrow faces: d plus the narrow face's width square to the edge,
      // 0.15 cos(lean) when the narrow faces are the leaning parallelograms (0.25,
      // 0.24942921, 0.24815325 at 0, 5, 9 degrees), else 0.15 (0.25).
      const double narrowLength = d + NarrowPier::kWidth * (inNarrow ? cosLean : 1);
      int vertical = 0;
      for (int e = 0; e < int(fm.edges.size()); ++e) {
        if (fm.edges[e].direction != EdgeDirection::Vertical) continue;
        ++vertical;
        int bricks = 0;
        for (const Cell& c : tex.cells()) {
          if (c.feature.kind != FeatureKind::Edge || c.feature.index != e) continue;
          ++bricks;
          const Vec3 along = c.axes.col(0);
          const double bottom = c.origin.z();
          INFO("edge " << e << " brick at " << c.origin.transpose() << " along " << along.transpose());
          const bool alongWide = std::abs(along.x()) > 0.98;  // x, or x tilted 9 degrees
          const bool topCourse = bottom > NarrowPier::kHeight - 1.5 * course;
          if (alongWide) {
            CHECK(c.size.x() == Approx(NarrowPier::kBrickLength).margin(1e-9));
          } else if (inNarrow || !topCourse) {
            // (Leaning in the wide faces' plane, the narrow faces lean and meet the top
            // at 81 or 99 degrees: on one side the top edge's cells, which fill the
            // region both layers share, reach d tan(lean) down the narrow face and
            // claim the top course's run there, so that brick is cut to the corner.)
            CHECK(c.size.x() == Approx(narrowLength).margin(1e-9));
          }
          // Level: the brick's end in its face (its two corners on the face) lies on
          // two course lines. A square box on a leaning edge misses them by
          // 0.4 sin(lean) (its bottom) or course (1 - cos(lean)) (its top). (In the top
          // course only its bottom is checked: at 5 degrees the top corners' cubes,
          // their axes the three faces' normals 5 degrees off square, reach d sin 5
          // below the top along two of the edges and claim that much of them.)
          int onCourse = 0;
          for (int k = 0; k < int(c.vertices().size()) / 2; ++k) {
            const Vec3 p = c.vertices()[size_t(k)];
            if (std::abs((p - c.origin).dot(along) - c.size.x()) > 1e-9) continue;
            ++onCourse;
            if (topCourse && p.z() > bottom + 0.5 * course) continue;
            const double lines = p.z() / course;
            CHECK(lines == Approx(std::round(lines)).margin(1e-9));
          }
          CHECK(onCourse == 2);
        }
        INFO("edge " << e);
        CHECK(bricks == 10);
      }
      CHECK(vertical == 4);

      // No brick of a vertical edge and no cell of a face reaches past the pier grown by
      // d on its sides and top. Below the ground a cell swept along a leaning face's
      // normal reaches d sin(lean) (0.0087156, 0.0156434) at its outer corner: the
      // face's layer does. (Left out: the top corners' cubes at 5 degrees, whose skewed
      // axes reach d sin 5 past the top's layer, and the top edges' cells, boxes around
      // the region two layers share where they meet 5 or 9 degrees off square, which
      // reach d sin(lean) past it: cornerBlock and alongEdge, not reachInto.)
      double past = -INFINITY, lowest = INFINITY;
      for (const Cell& c : tex.cells()) {
        if (c.feature.kind == FeatureKind::Corner) continue;
        if (c.feature.kind == FeatureKind::Edge && fm.edges[c.feature.index].direction != EdgeDirection::Vertical)
          continue;
        for (const Vec3& p : c.vertices())
          past = std::max(past, pastLeaningPierLayer(p, degrees, lean)), lowest = std::min(lowest, p.z());
      }
      CHECK(past <= 1e-9);
      CHECK(lowest >= -d * sinLean - 1e-9);

      // No two cells overlap.
      int overlapping = 0;
      const std::vector<Cell>& cells = tex.cells();
      for (size_t a = 0; a < cells.size(); ++a)
        for (size_t b = a + 1; b < cells.size(); ++b) overlapping += cellsOverlap(cells[a], cells[b], 1e-9);
      CHECK(overlapping == 0);
    }
}
