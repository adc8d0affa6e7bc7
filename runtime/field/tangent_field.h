// A vector or tensor field on a surface mesh (FGSG §4.2, §4.3): values stored
// at vertices in their tangent frames, interpolated continuously inside triangles by the
// piecewise scheme of Zhang et al. 2007: the three corner values are transported into
// the face plane (minimal rotation of the vertex normal onto the face normal) and blended
// barycentrically. Every query of FGSG §4.3 is answered here: the value, eigenvalues and
// eigenvectors, Jacobian / tensor gradient (constant per face), divergence and curl, the
// angle to a scope axis, lengths; and what tracing needs (DirectionField).
//
// Local quantities (tensor(), jacobian(), tensorGradient()) are in the face frame of the
// point's face (TangentFrames::faceFrame). World vectors (vector(), eigen()) lie in the
// tangent plane of the point's smooth normal, p.normal(mesh): the face-plane result is
// carried there by the minimal rotation of the face normal onto it.
//
// A tensor field is symmetric unless it is given a rotational part (setVertexRotations):
// then T = S + w J, S the symmetric tensor, J the quarter turn [[0, -1], [1, 0]] — an
// asymmetric tensor field, whose eigenvectors meet at any angle (FGSG §4.2, after Zhang
// et al. 2009, "Asymmetric tensor analysis for flow visualization"). w is the same in
// every right-handed frame, so it is interpolated as a number.
//
// Editing (set*) is not thread-safe; once edits are done any number of threads may query
// at the same time (the degeneracy cache is built once, under a lock).
#pragma once

#include "runtime/field/direction_field.h"
#include "runtime/field/tangent_frames.h"

#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

namespace fgsg::rt::field {

enum class FieldType { Vector, Tensor };
// Which eigenvector field a tensor query means (vector fields ignore it).
enum class Eigenvector { Major, Minor };

// Eigen decomposition at a point: value1 >= value2; vector1, vector2 unit, world, with
// vector2 = n x vector1 (an asymmetric tensor's: on vector1's counter-clockwise side, at
// the angle between its eigenvectors; PlaneEigen). A vector field answers value1 = its length, value2 = 0, vector1 =
// its direction. Where the direction is undefined (a zero vector, an isotropic tensor)
// the vectors are the frame's axes: ask direction() whether they mean anything.
struct Eigen2 {
  double value1 = 0, value2 = 0;
  Vec3 vector1 = Vec3::UnitX(), vector2 = Vec3::UnitY();
};

// The gradient of a tensor field, in the face frame: dT/dx and dT/dy (constant per face).
struct TensorGradient {
  Mat2 dx = Mat2::Zero(), dy = Mat2::Zero();
};

class TangentField : public DirectionField {
 public:
  // A zero field of the given type over the frames' mesh.
  TangentField(std::shared_ptr<const TangentFrames> frames, FieldType type);
  TangentField(const TangentField& other);
  TangentField& operator=(const TangentField& other);

  FieldType type() const { return type_; }
  bool isTensor() const { return type_ == FieldType::Tensor; }
  const TangentFrames& frames() const { return *frames_; }
  const std::shared_ptr<const TangentFrames>& sharedFrames() const { return frames_; }
  const SurfaceMesh& mesh() const { return frames_->mesh(); }
  size_t vertexCount() const { return frames_->vertexCount(); }

  // ---- values at vertices, in the vertex frames ----
  // Vector fields use the vectors, tensor fields the (symmetric) tensors.
  const Vec2& vertexVector(int v) const { return vectors_[v]; }
  const Mat2& vertexTensor(int v) const { return tensors_[v]; }
  const std::vector<Vec2>& vertexVectors() const { return vectors_; }
  const std::vector<Mat2>& vertexTensors() const { return tensors_; }
  void setVertexVector(int v, const Vec2& value);
  void setVertexTensor(int v, const Mat2& value);  // symmetrised
  void setVertexVectors(std::vector<Vec2> values);
  void setVertexTensors(std::vector<Mat2> values);
  // An asymmetric tensor field's rotational parts w, one per vertex (tensor fields only;
  // an empty list makes the field symmetric again).
  void setVertexRotations(std::vector<double> values);
  bool isAsymmetric() const { return !rotations_.empty(); }
  double vertexRotation(int v) const { return rotations_.empty() ? 0.0 : rotations_[v]; }
  // A 3x3 world tensor restricted to the tangent plane, E^T T E, kept whole: its
  // symmetric part and its rotational part (makes the field asymmetric).
  void setVertexAsymmetricWorld(int v, const Mat3& value);
  // E (S + w J) E^T.
  Mat3 vertexAsymmetricWorld(int v) const;
  // World forms: a vector is projected onto the tangent plane, a 3x3 tensor restricted to
  // it (E^T T E with E = [e1 e2]); reading back gives E v and E T E^T.
  void setVertexVectorWorld(int v, const Vec3& value);
  void setVertexTensorWorld(int v, const Mat3& value);
  Vec3 vertexVectorWorld(int v) const;
  Mat3 vertexTensorWorld(int v) const;

  // The corner values of face f transported into its frame. A vector field's "tensor" is
  // v v^T / |v| (eigenvalues |v| and 0, major eigenvector v).
  std::array<Vec2, 3> cornerVectors(int f) const;
  std::array<Mat2, 3> cornerTensors(int f) const;

  // ---- evaluation at a surface point ----
  // The interpolated value in the face frame.
  Vec2 localVector(const SurfacePoint& p) const;  // a tensor field: value1 * vector1
  Mat2 tensor(const SurfacePoint& p) const;  // the symmetric part S
  double rotation(const SurfacePoint& p) const;  // the rotational part w (0: symmetric)
  // The world tangent vector: the vector, or a tensor's major eigenvector scaled by its
  // eigenvalue (its sign is arbitrary).
  Vec3 vector(const SurfacePoint& p) const;
  Eigen2 eigen(const SurfacePoint& p) const;
  double length1(const SurfacePoint& p) const { return std::abs(eigen(p).value1); }
  double length2(const SurfacePoint& p) const { return std::abs(eigen(p).value2); }
  // The Jacobian of the vector field, or of a tensor's eigenvector field (the eigenvector
  // scaled by its |eigenvalue|, corner signs aligned with the one at p), in the face
  // frame: J(i, j) = d v_i / d x_j. Constant per face for vector fields.
  Mat2 jacobian(const SurfacePoint& p, Eigenvector which = Eigenvector::Major) const;
  // The same as a world 3x3 map of the tangent plane, E J E^T (face frame axes E).
  Mat3 jacobianWorld(const SurfacePoint& p, Eigenvector which = Eigenvector::Major) const;
  // The interpolated tensor as a world 3x3 tensor of the face plane, E T E^T (a vector
  // field's: v v^T / |v|; an asymmetric one's whole, S + w J).
  Mat3 tensorWorld(const SurfacePoint& p) const;
  TensorGradient tensorGradient(const SurfacePoint& p) const;
  // trace(J), and J(1,0) - J(0,1) (counter-clockwise about the face normal positive).
  double divergence(const SurfacePoint& p, Eigenvector which = Eigenvector::Major) const;
  double curl(const SurfacePoint& p, Eigenvector which = Eigenvector::Major) const;
  // The signed angle in degrees from `axis` (projected onto the tangent plane at p) to
  // vector1 or vector2, counter-clockwise about the normal: (-180, 180] for vector
  // fields, (-90, 90] for tensors (a line has no sign). 0 where either is undefined.
  double angle(const SurfacePoint& p, const Vec3& axis,
               Eigenvector which = Eigenvector::Major) const;

  // ---- DirectionField ----
  bool direction(const SurfacePoint& p, Vec3& out) const override;
  bool isLineField() const override { return isTensor(); }
  const std::vector<Degeneracy>& degeneraciesIn(int face) const override;
  // Every degenerate point, ordered by face.
  const std::vector<Degeneracy>& degeneracies() const;

 private:
  void invalidate() { cacheReady_.store(false, std::memory_order_release); }
  void buildCache() const;
  // The eigenvector field's corner values, signs aligned with the direction at p.
  std::array<Vec2, 3> eigenvectorCorners(const SurfacePoint& p, Eigenvector which) const;
  std::array<double, 3> cornerRotations(int f) const;
  Mat2 jacobianOf(int face, const std::array<Vec2, 3>& corners) const;

  std::shared_ptr<const TangentFrames> frames_;
  FieldType type_;
  std::vector<Vec2> vectors_;
  std::vector<Mat2> tensors_;
  std::vector<double> rotations_;  // empty: symmetric

  mutable std::mutex cacheMutex_;
  mutable std::atomic<bool> cacheReady_{false};
  mutable std::vector<std::vector<Degeneracy>> perFace_;
  mutable std::vector<Degeneracy> all_;
};

// Eigen decomposition of a symmetric 2x2 tensor: values (major first) and the angle of
// the major eigenvector, in (-pi/2, pi/2].
struct LocalEigen {
  double value1 = 0, value2 = 0, angle = 0;
};
LocalEigen eigenOf(const Mat2& t);

// Eigen analysis of the asymmetric tensor S + w J in the plane (S symmetric, with mean m
// and deviator r). Real domain, |w| <= r: the eigenvalues m +- sqrt(r^2 - w^2) and their
// unit eigenvectors, which turn from S's towards each other as |w| grows and meet at
// |w| = r. Complex domain, |w| > r: no real eigenvector; the eigenvalues' real part m
// twice and S's eigenvectors, the dual-eigenvectors of Zhang et al. 2009. vector2 is on
// vector1's counter-clockwise side; for w = 0 it is vector1 turned a quarter.
struct PlaneEigen {
  double value1 = 0, value2 = 0;
  Vec2 vector1 = Vec2::UnitX(), vector2 = Vec2::UnitY();
  bool real = true;
};
PlaneEigen eigenOf(const Mat2& symmetric, double rotation);

}  // namespace fgsg::rt::field
