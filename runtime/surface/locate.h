// Point location on a surface: the exact closest surface point to any point in space
// (snapping a grammar's seed or a scope's origin onto the surface), and the surface points
// at a vertex or on an edge that tracing starts from and crosses.
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <vector>

namespace fgsg::rt::surface {

// The closest point to p on triangle (a, b, c) and its barycentric coordinates there
// (all >= 0, summing to 1). The triangle must not be degenerate.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& bary);

// A bounding-volume hierarchy over the faces, built once; queries are read-only and may
// run in parallel. Keeps a reference to the mesh, which must outlive it unchanged.
class SurfaceLocator {
 public:
  explicit SurfaceLocator(const SurfaceMesh& mesh);
  SurfaceLocator(SurfaceMesh&&) = delete;  // it would outlive a temporary mesh

  // The surface point closest to p (exact, up to rounding; ties go to the face found
  // first; for points beyond 1e12 surface sizes, the closest to a point that far in p's
  // direction). Invalid only for a mesh without faces or a p with a NaN coordinate.
  // `distance`, when given, receives |p - q|.
  SurfacePoint closestPoint(const Vec3& p, double* distance = nullptr) const;

  const SurfaceMesh& mesh() const { return mesh_; }

 private:
  struct Node {
    Vec3 lo, hi;
    int first = 0, count = 0;  // a leaf: faces order_[first, first + count)
    int right = -1;            // an inner node: children at index + 1 and `right`
  };
  int build(int first, int count, std::vector<Vec3>& centroids);
  Vec3 withinRange(const Vec3& p) const;

  const SurfaceMesh& mesh_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

// One-off query: builds a SurfaceLocator and asks it (build one yourself for many queries).
SurfacePoint closestPoint(const SurfaceMesh& mesh, const Vec3& p);

// The surface point at vertex v, in one of its faces (needs buildTopology()); invalid for
// an isolated vertex.
SurfacePoint atVertex(const SurfaceMesh& mesh, int v);
// The point at parameter t in [0, 1] along edge k of `face`, from faces[face][k] (t = 0)
// to faces[face][(k + 1) % 3] (t = 1).
SurfacePoint atEdge(const SurfaceMesh& mesh, int face, int k, double t);

}  // namespace fgsg::rt::surface
