#include "runtime/field/tangent_frames.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::field {

namespace {

// Below this squared length a projected edge is treated as zero (a degenerate face or an
// edge along the normal), and the frame falls back to an arbitrary tangent direction.
constexpr double kTinySquared = 1e-28;
// 1 + cos(angle between the normals) below this: the normals are opposite.
constexpr double kOppositeNormals = 1e-12;

Vec3 anyOrthogonal(const Vec3& n) {
  const Vec3 a = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (a - a.dot(n) * n).normalized();
}

// A frame with normal n whose e1 is `direction` projected onto the tangent plane.
Frame frameFrom(const Vec3& n, const Vec3& direction) {
  Frame f;
  f.n = n;
  Vec3 e1 = direction - direction.dot(n) * n;
  f.e1 = e1.squaredNorm() > kTinySquared ? Vec3(e1.normalized()) : anyOrthogonal(n);
  f.e2 = n.cross(f.e1);
  return f;
}

// The rotation that maps coordinates in frame `from` to coordinates in frame `to` after
// carrying `from` onto `to`'s plane by the minimal rotation of the normals.
Rot2 transport(const Frame& from, const Frame& to) {
  const Vec3 e1 = minimalRotation(from.n, to.n, from.e1);
  const Rot2 r(e1.dot(to.e1), e1.dot(to.e2));
  const double len = std::abs(r);
  return len > 0 ? r / len : Rot2(1, 0);
}

}  // namespace

Mat2 Frame::tensorToLocal(const Mat3& world) const {
  Eigen::Matrix<double, 3, 2> E;
  E << e1, e2;
  return E.transpose() * world * E;
}

Mat3 Frame::tensorToWorld(const Mat2& local) const {
  Eigen::Matrix<double, 3, 2> E;
  E << e1, e2;
  return E * local * E.transpose();
}

Vec2 rotate(const Rot2& r, const Vec2& v) {
  return {r.real() * v.x() - r.imag() * v.y(), r.imag() * v.x() + r.real() * v.y()};
}

Mat2 rotate(const Rot2& r, const Mat2& t) {
  Mat2 R;
  R << r.real(), -r.imag(), r.imag(), r.real();
  return R * t * R.transpose();
}

Vec3 minimalRotation(const Vec3& from, const Vec3& to, const Vec3& u) {
  const double c = from.dot(to);
  if (1 + c < kOppositeNormals) {
    const Vec3 k = anyOrthogonal(from);
    return 2 * k.dot(u) * k - u;  // half a turn about k
  }
  // Rodrigues with axis * sin = from x to: R = I + [v]x + [v]x^2 / (1 + c).
  const Vec3 v = from.cross(to);
  const Vec3 vu = v.cross(u);
  return u + vu + v.cross(vu) / (1 + c);
}

TangentFrames::TangentFrames(const SurfaceMesh& mesh) : mesh_(&mesh) {
  const size_t nv = mesh.vertexCount(), nf = mesh.faceCount();
  face_.resize(nf);
  corners_.resize(nf);
  inverseEdges_.resize(nf);
  for (size_t f = 0; f < nf; ++f) {
    const auto& t = mesh.faces[f];
    const Vec3& p0 = mesh.vertices[t[0]];
    face_[f] = frameFrom(mesh.faceNormals[f], mesh.vertices[t[1]] - p0);
    for (int k = 0; k < 3; ++k) corners_[f][k] = face_[f].toLocal(mesh.vertices[t[k]] - p0);
    Mat2 D;
    D << corners_[f][1], corners_[f][2];
    // A degenerate face has no gradients: its barycentric derivatives are left zero.
    const double det = D.determinant();
    inverseEdges_[f] = std::abs(det) > kTinySquared ? Mat2(D.inverse()) : Mat2::Zero();
  }
  vertex_.resize(nv);
  for (size_t v = 0; v < nv; ++v) {
    const int f = mesh.vertexFace[v];
    const Vec3 n = mesh.vertexNormals[v];
    if (f < 0) {
      vertex_[v] = frameFrom(n, anyOrthogonal(n));
      continue;
    }
    const int k = mesh.cornerOf(f, int(v));
    vertex_[v] = frameFrom(n, mesh.vertices[mesh.faces[f][(k + 1) % 3]] - mesh.vertices[v]);
  }
  toFace_.resize(nf);
  for (size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) toFace_[f][k] = transport(vertex_[mesh.faces[f][k]], face_[f]);

  // Vertex rings from the edges of the faces, each neighbour once.
  std::vector<std::pair<int, int>> edges;
  edges.reserve(6 * nf);
  for (const auto& t : mesh.faces)
    for (int k = 0; k < 3; ++k) {
      edges.push_back({t[k], t[(k + 1) % 3]});
      edges.push_back({t[(k + 1) % 3], t[k]});
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  ringStart_.assign(nv + 1, 0);
  for (const auto& e : edges) ++ringStart_[e.first + 1];
  for (size_t v = 0; v < nv; ++v) ringStart_[v + 1] += ringStart_[v];
  ring_.resize(edges.size());
  ringToVertex_.resize(edges.size());
  for (size_t i = 0; i < edges.size(); ++i) {
    ring_[i] = edges[i].second;
    ringToVertex_[i] = transport(vertex_[edges[i].second], vertex_[edges[i].first]);
  }
}

Frame TangentFrames::frameAt(const SurfacePoint& p) const {
  const Frame& f = face_[p.face];
  const Vec3 n = p.normal(*mesh_);
  Frame out;
  out.n = n;
  out.e1 = minimalRotation(f.n, n, f.e1);
  out.e2 = n.cross(out.e1);
  return out;
}

}  // namespace fgsg::rt::field
