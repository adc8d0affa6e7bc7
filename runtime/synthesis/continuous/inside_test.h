// Inside or outside the example solid, for the many points its labels are read at
// (labels.cpp: a few points off every edge and vertex). windingNumber() sums a solid
// angle over every face, O(faces) a point: 25 000 faces took minutes. Here a point's ray
// (one fixed direction, parallel to no face) is tested only against the triangles whose
// projections along the ray cover it, found in a grid: the signed crossings are the
// winding number. A point whose ray grazes an edge, or that lies on a face, falls back
// to windingNumber(), so the answer is the same.
//
// The nearest vertex, also asked at every such point, comes from a k-d tree.
#pragma once

#include "runtime/synthesis/continuous/example_solid.h"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace fgsg::rt::synthesis::continuous {

class InsideTest {
 public:
  explicit InsideTest(const ExampleSolid& solid);
  // windingNumber(solid, p) > 0.5.
  bool inside(const DVec3& p) const;
  // How many points fell back to windingNumber() (tests).
  uint64_t fallbacks() const { return fallbacks_; }

 private:
  struct Triangle {
    Eigen::Vector3d a, n;           // a corner and the (unnormalised) outward normal
    Eigen::Vector2d p[3];           // the corners projected along the ray
    double tol[3];                  // per edge: an edge function this small is on it
  };
  const ExampleSolid& solid_;
  Eigen::Vector3d ray_, u_, v_;     // the ray and two axes across it
  std::vector<Triangle> triangles_;
  Eigen::Vector2d lo_, cell_;       // the grid over the projections
  int nx_ = 0, ny_ = 0;
  std::vector<uint32_t> start_, entries_;  // per cell, its triangles (CSR)
  double onFace_ = 0;               // a ray parameter this small starts on a face
  mutable uint64_t fallbacks_ = 0;
};

// The distance from p to the nearest vertex of the solid that is not vertex `skip`
// (-1: any vertex).
class NearestVertex {
 public:
  explicit NearestVertex(const ExampleSolid& solid);
  ~NearestVertex();
  double distance(const DVec3& p, int skip) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace fgsg::rt::synthesis::continuous
