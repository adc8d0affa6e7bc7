// Tangent frames and field queries (FGSG §4.3) on analytic fields: linear vector fields
// are interpolated exactly on a flat mesh and their derivatives are exact; constant
// tensors have exact eigen decompositions; angles to scope axes; transports on curved
// meshes keep vectors tangent and are inverse pairs.
#include "runtime/field/tangent_field.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::field;

namespace fgsg::rt::field::testing {
SurfaceMesh flatGrid(int nx, int ny, double x0, double y0, double w, double h, double jitter);
SurfaceMesh icosphere(int subdivisions, double radius);
}  // namespace fgsg::rt::field::testing

namespace {

constexpr double kExact = 1e-12;
constexpr double kPi = 3.14159265358979323846;

// Deterministic pseudo-random numbers in [0, 1).
struct Lcg {
  uint64_t s = 88172645463325252ull;
  double operator()() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return (s >> 11) * (1.0 / 9007199254740992.0);
  }
};

SurfacePoint randomPoint(const SurfaceMesh& m, Lcg& rnd) {
  SurfacePoint p;
  p.face = int(rnd() * m.faceCount());
  double a = rnd(), b = rnd();
  if (a + b > 1) a = 1 - a, b = 1 - b;
  p.bary = Vec3(1 - a - b, a, b);
  return p;
}

}  // namespace

TEST_CASE("tangent frames are orthonormal, right-handed and tangent", "[field]") {
  const SurfaceMesh m = testing::icosphere(3, 2.0);
  const TangentFrames frames(m);
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const Frame& f = frames.vertexFrame(int(v));
    CHECK(f.e1.norm() == Approx(1).margin(kExact));
    CHECK(std::abs(f.e1.dot(f.n)) < kExact);
    CHECK((f.e1.cross(f.e2) - f.n).norm() < kExact);
    CHECK((f.n - m.vertexNormals[v]).norm() < kExact);
  }
  for (size_t f = 0; f < m.faceCount(); ++f) {
    const Frame& fr = frames.faceFrame(int(f));
    CHECK((fr.e1.cross(fr.e2) - m.faceNormals[f]).norm() < kExact);
  }
}

TEST_CASE("vertex-to-vertex transports are inverse pairs of rotations", "[field]") {
  const SurfaceMesh m = testing::icosphere(2, 1.0);
  const TangentFrames frames(m);
  for (int i = 0; i < int(m.vertexCount()); ++i)
    for (int r = frames.neighbourBegin(i); r < frames.neighbourEnd(i); ++r) {
      const int j = frames.neighbour(r);
      CHECK(std::abs(frames.neighbourToVertex(r)) == Approx(1).margin(kExact));
      // j's transport into i, composed with i's into j, is the identity.
      for (int q = frames.neighbourBegin(j); q < frames.neighbourEnd(j); ++q)
        if (frames.neighbour(q) == i)
          CHECK(std::abs(frames.neighbourToVertex(r) * frames.neighbourToVertex(q) - 1.0) < kExact);
    }
}

TEST_CASE("a linear vector field is interpolated exactly on a flat mesh", "[field]") {
  const SurfaceMesh m = testing::flatGrid(8, 6, -1, -0.5, 2, 1.5, 0.3);
  auto frames = TangentFrames::make(m);
  const double a = 0.7, b = -1.3, c = 0.25, d = 2.1, e = -0.4, f = 1.5;
  auto exact = [&](const Vec3& p) {
    return Vec3(a * p.x() + b * p.y() + c, d * p.x() + e * p.y() + f, 0);
  };
  TangentField field(frames, FieldType::Vector);
  for (size_t v = 0; v < m.vertexCount(); ++v)
    field.setVertexVectorWorld(int(v), exact(m.vertices[v]));
  Lcg rnd;
  for (int i = 0; i < 200; ++i) {
    const SurfacePoint p = randomPoint(m, rnd);
    const Vec3 want = exact(p.position(m));
    CHECK((field.vector(p) - want).norm() < kExact);
    CHECK(field.divergence(p) == Approx(a + e).margin(kExact));
    CHECK(field.curl(p) == Approx(d - b).margin(kExact));
    const Mat3 J = field.jacobianWorld(p);
    CHECK(J(0, 0) == Approx(a).margin(kExact));
    CHECK(J(0, 1) == Approx(b).margin(kExact));
    CHECK(J(1, 0) == Approx(d).margin(kExact));
    CHECK(J(1, 1) == Approx(e).margin(kExact));
    CHECK(J.row(2).norm() < kExact);
    CHECK(J.col(2).norm() < kExact);
    const Eigen2 eig = field.eigen(p);
    CHECK(eig.value1 == Approx(want.norm()).margin(kExact));
    CHECK(eig.value2 == 0);
    CHECK((eig.vector1 - want.normalized()).norm() < 1e-10);
    CHECK((eig.vector2 - Vec3::UnitZ().cross(eig.vector1)).norm() < kExact);
    CHECK(field.length1(p) == Approx(want.norm()).margin(kExact));
  }
}

TEST_CASE("a linear tensor field and its gradient are exact on a flat mesh", "[field]") {
  const SurfaceMesh m = testing::flatGrid(6, 6, 0, 0, 1, 1, 0.3);
  auto frames = TangentFrames::make(m);
  // T(x, y) = T0 + x Tx + y Ty (world XY components).
  Mat2 T0, Tx, Ty;
  T0 << 1.0, 0.3, 0.3, -0.5;
  Tx << 0.4, -0.2, -0.2, 1.1;
  Ty << -0.7, 0.9, 0.9, 0.2;
  auto exact = [&](const Vec3& p) {
    const Mat2 t = T0 + p.x() * Tx + p.y() * Ty;
    Mat3 w = Mat3::Zero();
    w.block<2, 2>(0, 0) = t;
    return w;
  };
  TangentField field(frames, FieldType::Tensor);
  for (size_t v = 0; v < m.vertexCount(); ++v)
    field.setVertexTensorWorld(int(v), exact(m.vertices[v]));
  Lcg rnd;
  for (int i = 0; i < 100; ++i) {
    const SurfacePoint p = randomPoint(m, rnd);
    const Frame& fr = frames->faceFrame(p.face);
    CHECK((fr.tensorToWorld(field.tensor(p)) - exact(p.position(m))).norm() < kExact);
    // The gradient in the face frame, mapped back to world XY: dT/dworld_x = sum over
    // face axes k of (e_k . x) dT/dx_k, expressed in world components.
    const TensorGradient g = field.tensorGradient(p);
    const Mat3 dx = fr.tensorToWorld(g.dx) * fr.e1.x() + fr.tensorToWorld(g.dy) * fr.e2.x();
    const Mat3 dy = fr.tensorToWorld(g.dx) * fr.e1.y() + fr.tensorToWorld(g.dy) * fr.e2.y();
    CHECK((dx.block<2, 2>(0, 0) - Tx).norm() < 1e-11);
    CHECK((dy.block<2, 2>(0, 0) - Ty).norm() < 1e-11);
  }
}

TEST_CASE("a constant tensor's eigenvalues and eigenvectors are exact", "[field]") {
  const SurfaceMesh m = testing::flatGrid(4, 4, 0, 0, 1, 1, 0.4);
  auto frames = TangentFrames::make(m);
  // Major eigenvalue 3 along 35 degrees, minor -1 across it.
  const double angle = 35 * kPi / 180;
  const Vec3 u(std::cos(angle), std::sin(angle), 0), w(-std::sin(angle), std::cos(angle), 0);
  const Mat3 T = 3 * u * u.transpose() - 1 * w * w.transpose();
  TangentField field(frames, FieldType::Tensor);
  for (size_t v = 0; v < m.vertexCount(); ++v) field.setVertexTensorWorld(int(v), T);
  Lcg rnd;
  for (int i = 0; i < 50; ++i) {
    const SurfacePoint p = randomPoint(m, rnd);
    const Eigen2 e = field.eigen(p);
    CHECK(e.value1 == Approx(3).margin(kExact));
    CHECK(e.value2 == Approx(-1).margin(kExact));
    CHECK(std::abs(std::abs(e.vector1.dot(u)) - 1) < kExact);
    CHECK(std::abs(std::abs(e.vector2.dot(w)) - 1) < kExact);
    CHECK((field.vector(p).cwiseAbs() - 3 * u.cwiseAbs()).norm() < 1e-11);
    Vec3 dir;
    REQUIRE(field.direction(p, dir));
    CHECK(std::abs(std::abs(dir.dot(u)) - 1) < kExact);
    // A constant field's eigenvector fields have no derivatives.
    CHECK(std::abs(field.divergence(p)) < 1e-10);
    CHECK(std::abs(field.curl(p, Eigenvector::Minor)) < 1e-10);
    // Angles to scope axes, a line's folded into (-90, 90].
    CHECK(field.angle(p, Vec3::UnitX()) == Approx(35).margin(1e-9));
    CHECK(field.angle(p, Vec3::UnitY()) == Approx(-55).margin(1e-9));
    CHECK(field.angle(p, -Vec3::UnitX()) == Approx(35).margin(1e-9));
    CHECK(field.angle(p, Vec3::UnitX(), Eigenvector::Minor) == Approx(-55).margin(1e-9));
  }
  CHECK(field.isLineField());
}

TEST_CASE("vector angles are signed and span a full turn, zero fields have no direction",
          "[field]") {
  const SurfaceMesh m = testing::flatGrid(3, 3, 0, 0, 1, 1, 0.2);
  auto frames = TangentFrames::make(m);
  TangentField field(frames, FieldType::Vector);
  const double angle = 150 * kPi / 180;
  for (size_t v = 0; v < m.vertexCount(); ++v)
    field.setVertexVectorWorld(int(v), Vec3(std::cos(angle), std::sin(angle), 0.7));
  SurfacePoint p;
  p.face = 5;
  CHECK(field.angle(p, Vec3::UnitX()) == Approx(150).margin(1e-9));
  CHECK(field.angle(p, Vec3::UnitY()) == Approx(60).margin(1e-9));
  CHECK(field.angle(p, -Vec3::UnitY()) == Approx(-120).margin(1e-9));
  CHECK(field.length1(p) == Approx(1).margin(kExact));  // the normal part was dropped
  CHECK_FALSE(field.isLineField());
  TangentField zero(frames, FieldType::Vector);
  Vec3 dir;
  CHECK_FALSE(zero.direction(p, dir));
  CHECK(zero.angle(p, Vec3::UnitX()) == 0);
  TangentField isotropic(frames, FieldType::Tensor);
  for (size_t v = 0; v < m.vertexCount(); ++v)
    isotropic.setVertexTensor(int(v), 2 * Mat2::Identity());
  CHECK_FALSE(isotropic.direction(p, dir));
  CHECK(isotropic.eigen(p).value1 == Approx(2));
  CHECK(isotropic.eigen(p).value2 == Approx(2));
}

TEST_CASE("on a curved mesh values stay tangent and agree at vertices and across edges",
          "[field]") {
  const SurfaceMesh m = testing::icosphere(4, 1.0);
  auto frames = TangentFrames::make(m);
  // The rotation field about Z: v = z x p (tangent to the sphere).
  TangentField field(frames, FieldType::Vector);
  for (size_t v = 0; v < m.vertexCount(); ++v)
    field.setVertexVectorWorld(int(v), Vec3::UnitZ().cross(m.vertices[v]));
  Lcg rnd;
  for (int i = 0; i < 200; ++i) {
    const SurfacePoint p = randomPoint(m, rnd);
    const Vec3 v = field.vector(p);
    CHECK(std::abs(v.dot(p.normal(m))) < kExact);
    // Close to the smooth field (the mesh is a polyhedron: a few per cent).
    const Vec3 want = Vec3::UnitZ().cross(p.position(m));
    CHECK((v - want).norm() < 0.02);
    Vec3 dir;
    if (field.direction(p, dir)) CHECK(std::abs(dir.dot(p.normal(m))) < kExact);
  }
  for (size_t f = 0; f < m.faceCount(); f += 7) {
    for (int k = 0; k < 3; ++k) {
      // At a corner, every face gives back the vertex's own value.
      SurfacePoint corner;
      corner.face = int(f);
      corner.bary = Vec3::Zero();
      corner.bary[k] = 1;
      CHECK((field.vector(corner) - field.vertexVectorWorld(m.faces[f][k])).norm() < kExact);
      // At an edge midpoint the two faces agree up to the difference of their transports.
      const int g = m.neighbours[f][k];
      const int a = m.faces[f][k], b = m.faces[f][(k + 1) % 3];
      SurfacePoint pf, pg;
      pf.face = int(f);
      pf.bary = Vec3::Zero();
      pf.bary[k] = pf.bary[(k + 1) % 3] = 0.5;
      pg.face = g;
      pg.bary = Vec3::Zero();
      pg.bary[m.cornerOf(g, a)] = pg.bary[m.cornerOf(g, b)] = 0.5;
      CHECK((field.vector(pf) - field.vector(pg)).norm() < 1e-3);
    }
  }
}
