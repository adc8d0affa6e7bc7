// One cellular texture being laid on a base mesh (Legakis et al. 2001, §4): the base
// mesh's features, their occupancy maps, and the cells placed so far. Pattern
// generators (generators.h) place cells through add(); the caller walks order() —
// every corner, then every edge, then every face — and hands each feature to the
// generator its pattern tree picks.
//
//   CellularTexture tex(mesh, buildFeatureMesh(mesh), {});
//   for (FeatureRef f : tex.order()) layBricks(tex, f, {0.215, 0.075, 0.1025});
//   for (const Cell& c : tex.cells()) ... shrunk(c, joint) ...
//
// Every cell placed is projected onto the occupancy maps of the feature it was placed
// on and of the features next to it (a corner's edges and faces, an edge's faces), the
// paper's rule. add() also refuses, or shortens, a cell that would overlap one already
// placed: the occupancy maps are single-valued (§3), so where a pattern tree sends two
// neighbouring features patterns that both reach into the same corner, the first
// placed keeps it.
#pragma once

#include "runtime/cells/cell.h"
#include "runtime/cells/feature_mesh.h"
#include "runtime/cells/occupancy.h"

#include <unordered_map>
#include <vector>

namespace fgsg::rt::cells {

// The two faces at a point of an edge and the region both their cell layers share
// (§4: "a corner is the region where edges interact, an edge where faces interact").
struct EdgeSides {
  Vec3 point, tangent;        // tangent: along the edge, turned to point up when it is vertical
  Vec3 normal[2];             // outward normals of the left (A) and right (B) face
  Vec3 away[2];               // in each face's plane, perpendicular to the edge, into the face
  bool twoSided = false;      // false on the mesh boundary (B missing)
  bool swapped = false;       // A and B swapped to make the tangent point up
};

class CellularTexture {
 public:
  // `up`: world up (courses are horizontal); courses are counted from the lowest point
  // of the mesh.
  CellularTexture(const surface::SurfaceMesh& mesh, FeatureMesh features, const Vec3& up = Vec3::UnitZ());

  const surface::SurfaceMesh& mesh() const { return mesh_; }
  const FeatureMesh& features() const { return fm_; }
  const Vec3& up() const { return up_; }
  // The height of course 0's bottom along `up`.
  double courseBase() const { return courseBase_; }
  // A length below which differences are rounding (1e-9 of the mesh's size).
  double tolerance() const { return tolerance_; }

  // Every corner, then every edge, then every face (§4 "Ordering").
  std::vector<FeatureRef> order() const;

  IntervalSet& edgeMap(int e) { return edgeMaps_[e]; }
  const FaceOccupancy& faceMap(int f) const { return faceMaps_[f]; }
  EdgeSides sidesAt(int edge, double s) const;
  // The edge parameter (arc length) of p, not clamped to the edge.
  double edgeParameter(int edge, const Vec3& p) const;

  // Places a cell on feature `on`; false when it would overlap a cell already placed by
  // more than rounding and even a shortened cell (at least `keep` of its length, cut at
  // its far end along axis 0) would. The cell placed may be shorter than asked.
  bool add(Cell cell, FeatureRef on, double keep = 0.25);
  const std::vector<Cell>& cells() const { return cells_; }

 private:
  void project(const Cell& c, FeatureRef onto);
  // A cell's axis-aligned bounding box.
  struct Bounds {
    Vec3 lo, hi;
  };
  static Bounds boundsOf(const Cell& c);
  // Calls visit(key) for the key of every grid bucket the box meets.
  template <class Visit>
  void forBuckets(const Bounds& b, Visit&& visit) const;
  bool overlapsPlaced(const Cell& c) const;
  void index(int cell);

  const surface::SurfaceMesh& mesh_;
  FeatureMesh fm_;
  Vec3 up_;
  double courseBase_ = 0, tolerance_ = 1e-12;
  std::vector<IntervalSet> edgeMaps_;
  std::vector<FaceOccupancy> faceMaps_;
  std::vector<Cell> cells_;
  std::vector<Bounds> bounds_;  // per cell
  // A uniform hash grid of the cells' boxes, for the overlap check.
  double gridSize_ = 1;
  std::unordered_map<uint64_t, std::vector<int>> grid_;
  // The overlap check meets a cell once per bucket it shares: visited_[cell] == visit_
  // marks it seen in the current check.
  mutable std::vector<uint32_t> visited_;
  mutable uint32_t visit_ = 0;
};

// Whether two cells' boxes overlap by more than `slack` (separating axes).
bool cellsOverlap(const Cell& a, const Cell& b, double slack);

}  // namespace fgsg::rt::cells
