#include "runtime/field/tangent_field.h"

#include "runtime/field/singularities.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fgsg::rt::field {

namespace {

// A point's vector (or deviatoric tensor part) this much smaller than the largest at the
// face's corners counts as zero: the field has no direction there.
constexpr double kDegenerateRelative = 1e-12;

// Half the difference of the eigenvalues: how anisotropic a symmetric tensor is.
double deviatoric(const Mat2& t) {
  return std::hypot(0.5 * (t(0, 0) - t(1, 1)), 0.5 * (t(0, 1) + t(1, 0)));
}

Vec2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

// The quarter turn: w J is the rotational part of an asymmetric tensor.
const Mat2 kQuarterTurn = (Mat2() << 0, -1, 1, 0).finished();

// Of two solutions of the same eigenvector equation, the better conditioned, as a unit
// vector (zero when both vanish).
Vec2 longer(const Vec2& a, const Vec2& b) {
  const Vec2& v = a.squaredNorm() >= b.squaredNorm() ? a : b;
  const double n = v.norm();
  return n > 0 ? Vec2(v / n) : Vec2::Zero();
}

}  // namespace

PlaneEigen eigenOf(const Mat2& s, double w) {
  const LocalEigen e = eigenOf(s);
  const double mean = 0.5 * (e.value1 + e.value2), r = 0.5 * (e.value1 - e.value2);
  PlaneEigen out;
  out.vector1 = unit(e.angle);
  out.vector2 = unit(e.angle + std::numbers::pi / 2);
  if (w == 0) {
    out.value1 = e.value1, out.value2 = e.value2;
    return out;
  }
  out.real = std::abs(w) <= r;
  if (!out.real) {  // complex domain: the dual-eigenvectors
    out.value1 = out.value2 = mean;
    return out;
  }
  // The deviator [[h, b - w], [b + w, -h]] has eigenvalues +-mu; each row of
  // (D -+ mu I) v = 0 gives a solution, the longer one is better conditioned.
  const double h = 0.5 * (s(0, 0) - s(1, 1)), b = 0.5 * (s(0, 1) + s(1, 0));
  const double mu = std::sqrt(std::max(0.0, r * r - w * w));
  out.value1 = mean + mu;
  out.value2 = mean - mu;
  const Vec2 major = longer({b - w, mu - h}, {mu + h, b + w});
  Vec2 minor = longer({b - w, -(h + mu)}, {h - mu, b + w});
  if (major.squaredNorm() > 0) out.vector1 = major;
  if (minor.squaredNorm() > 0) out.vector2 = minor;
  if (out.vector1.x() * out.vector2.y() - out.vector1.y() * out.vector2.x() < 0) out.vector2 = -out.vector2;
  return out;
}

LocalEigen eigenOf(const Mat2& t) {
  const double mean = 0.5 * (t(0, 0) + t(1, 1));
  const double h = 0.5 * (t(0, 0) - t(1, 1)), b = 0.5 * (t(0, 1) + t(1, 0));
  const double r = std::hypot(h, b);
  return {mean + r, mean - r, 0.5 * std::atan2(b, h)};
}

TangentField::TangentField(std::shared_ptr<const TangentFrames> frames, FieldType type)
    : frames_(std::move(frames)), type_(type) {
  if (type_ == FieldType::Vector)
    vectors_.assign(frames_->vertexCount(), Vec2::Zero());
  else
    tensors_.assign(frames_->vertexCount(), Mat2::Zero());
}

TangentField::TangentField(const TangentField& other)
    : frames_(other.frames_), type_(other.type_), vectors_(other.vectors_),
      tensors_(other.tensors_), rotations_(other.rotations_) {}

TangentField& TangentField::operator=(const TangentField& other) {
  if (this == &other) return *this;
  frames_ = other.frames_;
  type_ = other.type_;
  vectors_ = other.vectors_;
  tensors_ = other.tensors_;
  rotations_ = other.rotations_;
  std::lock_guard<std::mutex> lock(cacheMutex_);
  perFace_.clear();
  all_.clear();
  invalidate();
  return *this;
}

void TangentField::setVertexVector(int v, const Vec2& value) {
  vectors_[v] = value;
  invalidate();
}

void TangentField::setVertexTensor(int v, const Mat2& value) {
  tensors_[v] = 0.5 * (value + value.transpose());
  invalidate();
}

void TangentField::setVertexVectors(std::vector<Vec2> values) {
  vectors_ = std::move(values);
  vectors_.resize(vertexCount(), Vec2::Zero());
  invalidate();
}

void TangentField::setVertexTensors(std::vector<Mat2> values) {
  tensors_ = std::move(values);
  tensors_.resize(vertexCount(), Mat2::Zero());
  for (Mat2& t : tensors_) t = 0.5 * (t + t.transpose()).eval();
  invalidate();
}

void TangentField::setVertexRotations(std::vector<double> values) {
  if (!isTensor() && !values.empty())
    throw std::logic_error("a vector field has no rotational part");
  rotations_ = std::move(values);
  if (!rotations_.empty()) rotations_.resize(vertexCount(), 0.0);
  invalidate();
}

void TangentField::setVertexAsymmetricWorld(int v, const Mat3& value) {
  const Frame& f = frames_->vertexFrame(v);
  Eigen::Matrix<double, 3, 2> E;
  E << f.e1, f.e2;
  const Mat2 local = E.transpose() * value * E;
  setVertexTensor(v, local);  // its symmetric part
  if (rotations_.empty()) rotations_.assign(vertexCount(), 0.0);
  rotations_[v] = 0.5 * (local(1, 0) - local(0, 1));
}

Mat3 TangentField::vertexAsymmetricWorld(int v) const {
  const Frame& f = frames_->vertexFrame(v);
  Eigen::Matrix<double, 3, 2> E;
  E << f.e1, f.e2;
  return E * (tensors_[v] + vertexRotation(v) * kQuarterTurn) * E.transpose();
}

void TangentField::setVertexVectorWorld(int v, const Vec3& value) {
  setVertexVector(v, frames_->vertexFrame(v).toLocal(value));
}

void TangentField::setVertexTensorWorld(int v, const Mat3& value) {
  const Mat3 symmetric = 0.5 * (value + value.transpose());
  setVertexTensor(v, frames_->vertexFrame(v).tensorToLocal(symmetric));
}

Vec3 TangentField::vertexVectorWorld(int v) const {
  return frames_->vertexFrame(v).toWorld(vectors_[v]);
}

Mat3 TangentField::vertexTensorWorld(int v) const {
  return frames_->vertexFrame(v).tensorToWorld(tensors_[v]);
}

std::array<Vec2, 3> TangentField::cornerVectors(int f) const {
  const auto& t = mesh().faces[f];
  std::array<Vec2, 3> out;
  for (int k = 0; k < 3; ++k) {
    if (!isTensor()) {
      out[k] = frames_->vectorToFace(f, k, vectors_[t[k]]);
    } else {
      const PlaneEigen e = eigenOf(frames_->tensorToFace(f, k, tensors_[t[k]]), vertexRotation(t[k]));
      out[k] = e.value1 * e.vector1;
    }
  }
  return out;
}

std::array<double, 3> TangentField::cornerRotations(int f) const {
  if (rotations_.empty()) return {0.0, 0.0, 0.0};
  const auto& t = mesh().faces[f];
  return {rotations_[t[0]], rotations_[t[1]], rotations_[t[2]]};
}

double TangentField::rotation(const SurfacePoint& p) const {
  if (rotations_.empty()) return 0.0;
  const auto w = cornerRotations(p.face);
  return p.bary[0] * w[0] + p.bary[1] * w[1] + p.bary[2] * w[2];
}

std::array<Mat2, 3> TangentField::cornerTensors(int f) const {
  const auto& t = mesh().faces[f];
  std::array<Mat2, 3> out;
  for (int k = 0; k < 3; ++k) {
    if (isTensor()) {
      out[k] = frames_->tensorToFace(f, k, tensors_[t[k]]);
    } else {
      const Vec2 v = frames_->vectorToFace(f, k, vectors_[t[k]]);
      const double len = v.norm();
      out[k] = len > 0 ? Mat2(v * v.transpose() / len) : Mat2::Zero();
    }
  }
  return out;
}

Vec2 TangentField::localVector(const SurfacePoint& p) const {
  if (isTensor()) {
    const PlaneEigen e = eigenOf(tensor(p), rotation(p));
    return e.value1 * e.vector1;
  }
  const auto c = cornerVectors(p.face);
  return p.bary[0] * c[0] + p.bary[1] * c[1] + p.bary[2] * c[2];
}

Mat2 TangentField::tensor(const SurfacePoint& p) const {
  if (!isTensor()) {
    const Vec2 v = localVector(p);
    const double len = v.norm();
    return len > 0 ? Mat2(v * v.transpose() / len) : Mat2::Zero();
  }
  const auto c = cornerTensors(p.face);
  return p.bary[0] * c[0] + p.bary[1] * c[1] + p.bary[2] * c[2];
}

Vec3 TangentField::vector(const SurfacePoint& p) const {
  return frames_->frameAt(p).toWorld(localVector(p));
}

Eigen2 TangentField::eigen(const SurfacePoint& p) const {
  const Frame fp = frames_->frameAt(p);
  Eigen2 out;
  double angle = 0;
  if (isTensor()) {
    const PlaneEigen e = eigenOf(tensor(p), rotation(p));
    out.value1 = e.value1;
    out.value2 = e.value2;
    out.vector1 = fp.toWorld(e.vector1);
    out.vector2 = fp.toWorld(e.vector2);
    return out;
  } else {
    const Vec2 v = localVector(p);
    out.value1 = v.norm();
    angle = out.value1 > 0 ? std::atan2(v.y(), v.x()) : 0.0;
  }
  out.vector1 = fp.toWorld(unit(angle));
  out.vector2 = fp.toWorld(unit(angle + std::numbers::pi / 2));
  return out;
}

std::array<Vec2, 3> TangentField::eigenvectorCorners(const SurfacePoint& p,
                                                     Eigenvector which) const {
  if (!isTensor()) return cornerVectors(p.face);
  const auto c = cornerTensors(p.face);
  const auto w = cornerRotations(p.face);
  const bool major = which == Eigenvector::Major;
  // The eigenvector at p orients the corners; at an isotropic p, the first corner's.
  const Mat2 tp = p.bary[0] * c[0] + p.bary[1] * c[1] + p.bary[2] * c[2];
  const PlaneEigen ep = eigenOf(tp, rotation(p));
  Vec2 reference = major ? ep.vector1 : ep.vector2;
  std::array<Vec2, 3> out;
  for (int k = 0; k < 3; ++k) {
    const PlaneEigen e = eigenOf(c[k], w[k]);
    out[k] = major ? Vec2(std::abs(e.value1) * e.vector1) : Vec2(std::abs(e.value2) * e.vector2);
  }
  if (deviatoric(tp) <= 0) {
    const PlaneEigen e0 = eigenOf(c[0], w[0]);
    reference = major ? e0.vector1 : e0.vector2;
  }
  for (Vec2& v : out)
    if (v.dot(reference) < 0) v = -v;
  return out;
}

Mat2 TangentField::jacobianOf(int face, const std::array<Vec2, 3>& c) const {
  Mat2 dv;
  dv << c[1] - c[0], c[2] - c[0];
  return dv * frames_->faceInverseEdges(face);
}

Mat2 TangentField::jacobian(const SurfacePoint& p, Eigenvector which) const {
  return jacobianOf(p.face, eigenvectorCorners(p, which));
}

Mat3 TangentField::jacobianWorld(const SurfacePoint& p, Eigenvector which) const {
  const Frame& f = frames_->faceFrame(p.face);
  Eigen::Matrix<double, 3, 2> E;
  E << f.e1, f.e2;
  return E * jacobian(p, which) * E.transpose();
}

Mat3 TangentField::tensorWorld(const SurfacePoint& p) const {
  const Frame& f = frames_->faceFrame(p.face);
  Eigen::Matrix<double, 3, 2> E;
  E << f.e1, f.e2;
  return E * (tensor(p) + rotation(p) * kQuarterTurn) * E.transpose();
}

TensorGradient TangentField::tensorGradient(const SurfacePoint& p) const {
  const auto c = cornerTensors(p.face);
  const Mat2& inv = frames_->faceInverseEdges(p.face);
  TensorGradient g;
  g.dx = (c[1] - c[0]) * inv(0, 0) + (c[2] - c[0]) * inv(1, 0);
  g.dy = (c[1] - c[0]) * inv(0, 1) + (c[2] - c[0]) * inv(1, 1);
  if (isAsymmetric()) {  // d(w J) = dw J
    const auto w = cornerRotations(p.face);
    g.dx += ((w[1] - w[0]) * inv(0, 0) + (w[2] - w[0]) * inv(1, 0)) * kQuarterTurn;
    g.dy += ((w[1] - w[0]) * inv(0, 1) + (w[2] - w[0]) * inv(1, 1)) * kQuarterTurn;
  }
  return g;
}

double TangentField::divergence(const SurfacePoint& p, Eigenvector which) const {
  return jacobian(p, which).trace();
}

double TangentField::curl(const SurfacePoint& p, Eigenvector which) const {
  const Mat2 J = jacobian(p, which);
  return J(1, 0) - J(0, 1);
}

double TangentField::angle(const SurfacePoint& p, const Vec3& axis, Eigenvector which) const {
  Vec3 dir;
  if (!direction(p, dir)) return 0;
  const Frame fp = frames_->frameAt(p);
  const Vec2 a = fp.toLocal(axis);
  if (a.squaredNorm() == 0) return 0;
  Vec2 u = fp.toLocal(dir);
  if (isTensor() && which == Eigenvector::Minor) {
    // The minor eigenvector: a quarter turn from the major one unless the tensor is
    // asymmetric (the same sign convention: on the major one's counter-clockwise side).
    const PlaneEigen e = eigenOf(tensor(p), rotation(p));
    const Vec2 major = e.vector1.dot(u) < 0 ? Vec2(-e.vector1) : e.vector1;
    u = e.vector2;
    if (major.x() * u.y() - major.y() * u.x() < 0) u = -u;
  }
  double ang = std::atan2(a.x() * u.y() - a.y() * u.x(), a.dot(u));
  if (isTensor()) {
    if (ang > std::numbers::pi / 2) ang -= std::numbers::pi;
    if (ang <= -std::numbers::pi / 2) ang += std::numbers::pi;
  }
  return ang * 180 / std::numbers::pi;
}

bool TangentField::direction(const SurfacePoint& p, Vec3& out) const {
  double scale = 0, magnitude = 0, angle = 0;
  if (isTensor()) {
    const auto c = cornerTensors(p.face);
    for (const Mat2& t : c) scale = std::max(scale, deviatoric(t));
    const Mat2 t = p.bary[0] * c[0] + p.bary[1] * c[1] + p.bary[2] * c[2];
    // Degenerate where the symmetric part is isotropic: an asymmetric tensor there has
    // complex eigenvalues, and its dual-eigenvectors are the symmetric part's.
    magnitude = deviatoric(t);
    const Vec2 major = eigenOf(t, rotation(p)).vector1;
    angle = std::atan2(major.y(), major.x());
  } else {
    const auto c = cornerVectors(p.face);
    for (const Vec2& v : c) scale = std::max(scale, v.norm());
    const Vec2 v = p.bary[0] * c[0] + p.bary[1] * c[1] + p.bary[2] * c[2];
    magnitude = v.norm();
    angle = std::atan2(v.y(), v.x());
  }
  if (!(magnitude > kDegenerateRelative * scale) || magnitude == 0) return false;
  out = frames_->frameAt(p).toWorld(unit(angle));
  return true;
}

void TangentField::buildCache() const {
  std::lock_guard<std::mutex> lock(cacheMutex_);
  if (cacheReady_.load(std::memory_order_acquire)) return;
  all_ = findDegeneracies(*this);
  perFace_.assign(mesh().faceCount(), {});
  for (const Degeneracy& d : all_) perFace_[d.face].push_back(d);
  cacheReady_.store(true, std::memory_order_release);
}

const std::vector<Degeneracy>& TangentField::degeneraciesIn(int face) const {
  if (!cacheReady_.load(std::memory_order_acquire)) buildCache();
  return perFace_[face];
}

const std::vector<Degeneracy>& TangentField::degeneracies() const {
  if (!cacheReady_.load(std::memory_order_acquire)) buildCache();
  return all_;
}

}  // namespace fgsg::rt::field
