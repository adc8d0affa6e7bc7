// Occupancy maps (Legakis et al. 2001, §3 "Occupancy maps"): what cells of neighbouring
// features already claimed, so that a pattern generator fills only the rest.
//  - An edge's map is one-dimensional: claimed intervals of arc length (the paper: an
//    array of booleans; intervals are exact and need no resolution).
//  - A face's map is two-dimensional, in the face's parameter space: initially the face
//    itself is free (its triangles; everything else, a window's hole included, is not),
//    and each claim is a convex polygon, the projection of a cell. The paper rasterises
//    both into a quadtree; generators here ask for whole courses ("which u are free for
//    every v in [v0, v1]?"), which the triangles and polygons answer exactly, with no
//    resolution to choose.
#pragma once

#include "runtime/cells/convex_polygon.h"
#include "runtime/cells/feature_mesh.h"

#include <vector>

namespace fgsg::rt::cells {

struct Interval {
  double lo = 0, hi = 0;
  double length() const { return hi - lo; }
};

// Disjoint intervals, sorted.
class IntervalSet {
 public:
  void add(double lo, double hi);
  // The parts of [lo, hi] no interval covers, in order (pieces shorter than `minimum`
  // dropped).
  std::vector<Interval> gaps(double lo, double hi, double minimum = 0) const;
  // Whether any interval overlaps (lo, hi) by more than `slack`.
  bool overlaps(double lo, double hi, double slack = 0) const;
  const std::vector<Interval>& intervals() const { return items_; }

 private:
  std::vector<Interval> items_;
};

// Within a list of sorted disjoint intervals, those of `a` that `b` also covers.
std::vector<Interval> intersect(const std::vector<Interval>& a, const std::vector<Interval>& b);
// The parts of the intervals of `a` that `b` does not cover.
std::vector<Interval> subtract(const std::vector<Interval>& a, const std::vector<Interval>& b);

class FaceOccupancy {
 public:
  // The face's triangles in its parameter space (faceAt / projectOnFace). A freeform
  // face has no parameterisation: its map is empty (nothing is free).
  FaceOccupancy(const FeatureFace& face, const surface::SurfaceMesh& mesh);

  // The u intervals where every point of the strip v0 <= v <= v1 lies on the face and
  // no claim reaches into the strip (a claim touching it only along v0 or v1 leaves it
  // free), pieces shorter than `minimum` dropped.
  std::vector<Interval> freeRuns(double v0, double v1, double minimum = 0) const;
  // The u intervals where the strip lies on the face, claims ignored.
  std::vector<Interval> insideRuns(double v0, double v1) const;
  // The heights strictly between v0 and v1 where a claim or the face's outline starts
  // or ends, sorted: the strip's free runs can only change there.
  std::vector<double> breaks(double v0, double v1) const;
  // The free part of convex `region` (the face within it minus every claim) as disjoint
  // convex pieces, exactly; pieces of area <= minArea are dropped. Clipped cells are
  // made of these.
  std::vector<Polygon2> freePieces(const Polygon2& region, double minArea) const;
  // The part of convex `region` on the face, claims ignored, as convex pieces.
  std::vector<Polygon2> insidePieces(const Polygon2& region, double minArea) const;
  // The u intervals the free part of the strip v0 <= v <= v1 reaches (the union of its
  // pieces' u extents): where a course's cells go when they may be clipped. Pieces of
  // area below `minimum` times the strip's height, and intervals shorter than `minimum`,
  // are dropped.
  std::vector<Interval> reachRuns(double v0, double v1, double minimum) const;
  // ... and the u intervals the face itself reaches in the strip, claims ignored.
  std::vector<Interval> insideReach(double v0, double v1, double minimum) const;
  // The face's area (in its parameters: metres on planar and cylindrical faces) and the
  // part of it no claim covers. Coverage is 1 - freeArea() / area(): cells count with
  // their share of the joints, as they claim it (docs/cells.md "Coverage").
  double area() const;
  double freeArea() const;
  double coverage() const { const double a = area(); return a > 0 ? 1 - freeArea() / a : 1; }
  // Marks a convex polygon (its corners in any order: their convex hull is taken) as
  // claimed.
  void claim(std::vector<Vec2> points);

  bool empty() const { return triangles_.empty(); }
  Vec2 lo() const { return lo_; }
  Vec2 hi() const { return hi_; }
  // A length below which differences are rounding: 1e-9 of the face's size.
  double tolerance() const { return tolerance_; }

 private:
  // The u intervals of the face along the line at v.
  std::vector<Interval> insideAt(double v) const;
  int bucketOf(double v) const;

  // The claims whose boxes meet [lo, hi] (each once).
  std::vector<int> claimsNear(const Vec2& lo, const Vec2& hi) const;
  std::vector<Interval> reachOf(const std::vector<Polygon2>& pieces, double minimum) const;

  std::vector<std::array<Vec2, 3>> triangles_;  // counter-clockwise
  // Each triangle's sides as the half-planes n . x <= c of its inside, and its box, so
  // that insidePieces clips against them without rebuilding them for every query.
  struct TriangleSides {
    std::array<Vec2, 3> n;
    std::array<double, 3> c;
    Vec2 lo, hi;
    bool proper;  // positive area (a degenerate triangle holds nothing)
  };
  std::vector<TriangleSides> triangleSides_;
  std::vector<double> vertexHeights_;      // the triangles' corners' v, sorted, distinct
  std::vector<std::vector<Vec2>> claims_;  // convex, counter-clockwise
  std::vector<Vec2> claimLo_, claimHi_;    // their boxes
  // Claims by v: bucket b holds those whose v-range meets it.
  std::vector<std::vector<int>> buckets_;
  Vec2 lo_ = Vec2::Zero(), hi_ = Vec2::Zero();
  double tolerance_ = 1e-12;
};

// The convex hull of `points`, counter-clockwise (Andrew's monotone chain).
std::vector<Vec2> convexHull(std::vector<Vec2> points);

}  // namespace fgsg::rt::cells
