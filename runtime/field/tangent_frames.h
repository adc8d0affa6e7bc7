// Tangent frames of a surface mesh (FGSG §4.2): fields store their values at vertices,
// each in the tangent plane of its vertex normal, in a local orthonormal frame. Within a
// triangle the three vertex values are compared in the triangle's own plane, so each
// (face, corner) pair has a transport: the minimal rotation taking the vertex normal to
// the face normal, then the face frame's coordinates. In 2D that transport is a plane
// rotation, stored as a unit complex number (vectors turn by it, tensors by its square).
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <Eigen/Core>

#include <array>
#include <complex>
#include <memory>
#include <vector>

namespace fgsg::rt::field {

using surface::SurfaceMesh;
using surface::SurfacePoint;
using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;
// A plane rotation by angle a, stored as cos a + i sin a.
using Rot2 = std::complex<double>;

// An orthonormal right-handed frame: e1, e2 span the tangent plane, n = e1 x e2.
struct Frame {
  Vec3 e1 = Vec3::UnitX(), e2 = Vec3::UnitY(), n = Vec3::UnitZ();

  Vec2 toLocal(const Vec3& world) const { return {world.dot(e1), world.dot(e2)}; }
  Vec3 toWorld(const Vec2& local) const { return local.x() * e1 + local.y() * e2; }
  // A 3x3 world tensor restricted to the tangent plane (E^T T E) and back (E T E^T).
  Mat2 tensorToLocal(const Mat3& world) const;
  Mat3 tensorToWorld(const Mat2& local) const;
};

// Rotations of local coordinates: a vector turns by r, a symmetric tensor T by R T R^T.
Vec2 rotate(const Rot2& r, const Vec2& v);
Mat2 rotate(const Rot2& r, const Mat2& t);

// The minimal rotation taking unit vector `from` to unit vector `to` (about from x to),
// applied to u. When from = -to the axis is any one orthogonal to `from`.
Vec3 minimalRotation(const Vec3& from, const Vec3& to, const Vec3& u);

class TangentFrames {
 public:
  // The mesh must have its topology built and must outlive the frames.
  explicit TangentFrames(const SurfaceMesh& mesh);
  static std::shared_ptr<const TangentFrames> make(const SurfaceMesh& mesh) {
    return std::make_shared<const TangentFrames>(mesh);
  }

  const SurfaceMesh& mesh() const { return *mesh_; }
  size_t vertexCount() const { return vertex_.size(); }
  size_t faceCount() const { return face_.size(); }

  // Vertex v: n = the vertex normal, e1 = the edge to the vertex after v in
  // mesh.faces[mesh.vertexFace[v]], projected onto the tangent plane; e2 = n x e1.
  const Frame& vertexFrame(int v) const { return vertex_[v]; }
  // Face f: n = the face normal, e1 = the edge from corner 0 to corner 1; e2 = n x e1.
  const Frame& faceFrame(int f) const { return face_[f]; }
  // The transport from the frame of corner k of face f into the face frame.
  const Rot2& vertexToFace(int f, int k) const { return toFace_[f][k]; }
  Vec2 vectorToFace(int f, int k, const Vec2& v) const { return rotate(toFace_[f][k], v); }
  Mat2 tensorToFace(int f, int k, const Mat2& t) const { return rotate(toFace_[f][k], t); }

  // The vertices sharing an edge with v, and for each the transport from its frame into
  // v's (minimal rotation of its normal onto v's), as index ranges into neighbour() and
  // neighbourToVertex().
  int neighbourBegin(int v) const { return ringStart_[v]; }
  int neighbourEnd(int v) const { return ringStart_[v + 1]; }
  int neighbour(int i) const { return ring_[i]; }
  const Rot2& neighbourToVertex(int i) const { return ringToVertex_[i]; }

  // Corner positions of face f in its frame (corner 0 at the origin) and the inverse of
  // [x1 - x0, x2 - x0]: row k - 1 of it is the gradient of barycentric coordinate k.
  const std::array<Vec2, 3>& faceCorners(int f) const { return corners_[f]; }
  const Mat2& faceInverseEdges(int f) const { return inverseEdges_[f]; }

  // The tangent frame at a surface point: the smooth normal there, and the face frame
  // carried onto that plane by the minimal rotation.
  Frame frameAt(const SurfacePoint& p) const;

 private:
  const SurfaceMesh* mesh_;
  std::vector<Frame> vertex_, face_;
  std::vector<std::array<Rot2, 3>> toFace_;
  std::vector<int> ringStart_, ring_;
  std::vector<Rot2> ringToVertex_;
  std::vector<std::array<Vec2, 3>> corners_;
  std::vector<Mat2> inverseEdges_;
};

}  // namespace fgsg::rt::field
