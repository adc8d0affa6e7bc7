// Asymmetric tensor fields (FGSG §4.2, after Zhang et al. 2009): the eigen analysis of
// S + w J in the real and complex domains, fields whose files carry whole tensors, and
// moves that keep their coordinates in the eigenvector basis.
#include "runtime/field/eigen_basis_direction.h"
#include "runtime/field/field_file.h"
#include "runtime/field/tangent_field.h"
#include "runtime/field/trace.h"
#include "runtime/surface/locate.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <optional>
#include <string>

using namespace fgsg::rt;
using namespace fgsg::rt::field;

namespace fgsg::rt::field::testing {
SurfaceMesh flatGrid(int nx, int ny, double x0, double y0, double w, double h, double jitter);
}  // namespace fgsg::rt::field::testing

namespace {

constexpr double kExact = 1e-12;
constexpr double kPi = 3.14159265358979323846;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
double degreesBetween(const Vec2& a, const Vec2& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180 / kPi;
}

// A field file of `grid` with the whole world tensor `value(x, y)` at each vertex.
std::string asymmetricFile(const SurfaceMesh& grid, const std::function<Mat3(const Vec3&)>& value) {
  std::string text = "fgsg-field 1 asymmetric " + std::to_string(grid.vertexCount()) + " world\n";
  for (const Vec3& p : grid.vertices) {
    const Mat3 T = value(p);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) text += std::to_string(T(r, c)) + (r == 2 && c == 2 ? "\n" : " ");
  }
  return text;
}

}  // namespace

TEST_CASE("the eigen analysis of an asymmetric tensor", "[field][asymmetric]") {
  // T = [[1, 0], [1, -1]] = S + w J with S = [[1, 0.5], [0.5, -1]], w = 0.5: eigenvalues
  // +-1, eigenvectors (2, 1)/sqrt 5 and (0, 1).
  const Mat2 T = (Mat2() << 1, 0, 1, -1).finished();
  const Mat2 S = 0.5 * (T + T.transpose());
  const PlaneEigen e = eigenOf(S, 0.5 * (T(1, 0) - T(0, 1)));
  CHECK(e.real);
  CHECK(e.value1 == Approx(1).margin(kExact));
  CHECK(e.value2 == Approx(-1).margin(kExact));
  CHECK(std::abs(e.vector1.dot(Vec2(2, 1).normalized())) == Approx(1).margin(kExact));
  CHECK(std::abs(e.vector2.dot(Vec2(0, 1))) == Approx(1).margin(kExact));
  CHECK(cross(e.vector1, e.vector2) > 0);
  CHECK((T * e.vector1 - e.value1 * e.vector1).norm() < kExact);
  CHECK((T * e.vector2 - e.value2 * e.vector2).norm() < kExact);

  // w = 0 is the symmetric analysis.
  const LocalEigen s = eigenOf(S);
  const PlaneEigen z = eigenOf(S, 0.0);
  CHECK(z.value1 == s.value1);
  CHECK(z.value2 == s.value2);
  CHECK((z.vector1 - Vec2(std::cos(s.angle), std::sin(s.angle))).norm() < kExact);
  CHECK((z.vector2 - Vec2(-std::sin(s.angle), std::cos(s.angle))).norm() < kExact);

  // S = diag(1, -1) (deviator r = 1): as w grows the eigenvectors close in, 90 - asin(w)
  // degrees apart, and meet halfway between S's at w = r; past it (the complex domain)
  // the values are the mean twice and the vectors S's, the dual-eigenvectors.
  const Mat2 D = Vec2(1, -1).asDiagonal();
  for (double w : {0.1, 0.5, 0.9, -0.7}) {
    INFO(w);
    const PlaneEigen a = eigenOf(D, w);
    CHECK(a.real);
    CHECK(degreesBetween(a.vector1, a.vector2) == Approx(90 - std::asin(std::abs(w)) * 180 / kPi).margin(1e-9));
    CHECK(a.value1 == Approx(std::sqrt(1 - w * w)).margin(kExact));
    const Mat2 A = D + w * (Mat2() << 0, -1, 1, 0).finished();
    CHECK((A * a.vector1 - a.value1 * a.vector1).norm() < 1e-12);
    CHECK((A * a.vector2 - a.value2 * a.vector2).norm() < 1e-12);
  }
  const PlaneEigen meet = eigenOf(D, 1.0), meetBelow = eigenOf(D, -1.0);
  CHECK(std::abs(meet.vector1.dot(Vec2(1, 1).normalized())) == Approx(1).margin(kExact));
  CHECK(std::abs(meet.vector2.dot(Vec2(1, 1).normalized())) == Approx(1).margin(kExact));
  CHECK(std::abs(meetBelow.vector1.dot(Vec2(1, -1).normalized())) == Approx(1).margin(kExact));
  const PlaneEigen complex = eigenOf(0.5 * D + Mat2::Identity(), 1.0);
  CHECK_FALSE(complex.real);
  CHECK(complex.value1 == 1);
  CHECK(complex.value2 == 1);
  CHECK((complex.vector1 - Vec2(1, 0)).norm() < kExact);
  CHECK((complex.vector2 - Vec2(0, 1)).norm() < kExact);
}

TEST_CASE("an asymmetric field file: whole tensors, read, queried and written back", "[field][asymmetric]") {
  const SurfaceMesh grid = testing::flatGrid(6, 6, -3, -3, 6, 6, 0.3);
  auto frames = TangentFrames::make(grid);
  Mat3 T = Mat3::Zero();
  T.block<2, 2>(0, 0) << 1, 0, 1, -1;
  std::optional<TangentField> f;
  std::string error;
  REQUIRE(parseField(asymmetricFile(grid, [&](const Vec3&) { return T; }), "a.tfield", frames, f, error));
  INFO(error);
  REQUIRE(f->isTensor());
  REQUIRE(f->isAsymmetric());
  const surface::SurfaceLocator locate(grid);
  const SurfacePoint p = locate.closestPoint(Vec3(0.3, -0.2, 0));
  CHECK((f->tensorWorld(p) - T).norm() < 1e-12);
  CHECK(f->rotation(p) == Approx(0.5).margin(1e-12));
  const Eigen2 e = f->eigen(p);
  CHECK(e.value1 == Approx(1).margin(1e-12));
  CHECK(std::abs(e.vector1.dot(Vec3(2, 1, 0).normalized())) == Approx(1).margin(1e-12));
  CHECK(std::abs(e.vector2.dot(Vec3(0, 1, 0))) == Approx(1).margin(1e-12));
  CHECK(e.vector1.cross(e.vector2).z() > 0);  // the minor one on the major one's left
  Vec3 dir;
  REQUIRE(f->direction(p, dir));
  CHECK(std::abs(dir.dot(Vec3(2, 1, 0).normalized())) == Approx(1).margin(1e-12));
  // The minor eigenvector's angle to X (in (-90, 90]) is 90 degrees, the major one's atan(1/2).
  CHECK(f->angle(p, Vec3::UnitX()) == Approx(std::atan(0.5) * 180 / kPi).margin(1e-9));
  CHECK(std::abs(f->angle(p, Vec3::UnitX(), Eigenvector::Minor)) == Approx(90).margin(1e-9));

  // Written and read back, in world and in frame coordinates: the same tensors.
  for (FieldCoordinates c : {FieldCoordinates::World, FieldCoordinates::Frame}) {
    std::optional<TangentField> back;
    REQUIRE(parseField(formatField(*f, c), "back.tfield", frames, back, error));
    CHECK(back->isAsymmetric());
    for (size_t v = 0; v < grid.vertexCount(); ++v) {
      CHECK((back->vertexTensor(int(v)) - f->vertexTensor(int(v))).norm() < 1e-12);
      CHECK(back->vertexRotation(int(v)) == Approx(f->vertexRotation(int(v))).margin(1e-12));
    }
  }
  CHECK(formatField(*f).rfind("# asymmetric field", 0) == 0);
  // A line with the symmetric tensor's six numbers is an error at its line.
  CHECK_FALSE(parseField("fgsg-field 1 asymmetric " + std::to_string(grid.vertexCount()) + "\n1 0 0 1 0 0\n",
                         "short.tfield", frames, f, error));
  CHECK(error == "short.tfield:2: expected 9 numbers, got 6");
}

TEST_CASE("a move in an asymmetric field keeps its coordinates in the eigenvector basis", "[field][asymmetric][trace]") {
  // S = diag(1, -1) everywhere and w = 0.15 x on [-2, 2]^2: the eigenvectors turn
  // towards each other as |w| grows. A move along the minor eigenvector stays on it;
  // keeping the angle to the major one (the symmetric rule) would leave it.
  const SurfaceMesh grid = testing::flatGrid(24, 24, -2, -2, 4, 4, 0);
  auto frames = TangentFrames::make(grid);
  auto tensorAt = [](const Vec3& p) {
    Mat3 T = Mat3::Zero();
    const double w = 0.15 * p.x();
    T.block<2, 2>(0, 0) << 1, -w, w, -1;
    return T;
  };
  std::optional<TangentField> f;
  std::string error;
  REQUIRE(parseField(asymmetricFile(grid, tensorAt), "w.tfield", frames, f, error));
  const surface::SurfaceLocator locate(grid);
  const SurfacePoint start = locate.closestPoint(Vec3(-1.0, -1.5, 0));
  const Eigen2 e0 = f->eigen(start);
  double a = 0, b = 0;
  REQUIRE(EigenBasisDirection::coordinates(*f, start, e0.vector2, a, b));
  CHECK(a == Approx(0).margin(1e-12));
  CHECK(b == Approx(1).margin(1e-12));
  // Coordinates of any vector reproduce it.
  double ca = 0, cb = 0;
  const Vec3 d = Vec3(0.3, 0.8, 0);
  REQUIRE(EigenBasisDirection::coordinates(*f, start, d, ca, cb));
  CHECK((ca * e0.vector1 + cb * e0.vector2 - d).norm() < 1e-12);

  const EigenBasisDirection minor(*f, 0.0, 1.0);
  for (double length : {1.0, 2.5}) {
    INFO(length);
    const TraceResult r = traceField(grid, minor, start, e0.vector2, 0.0, length);
    REQUIRE_FALSE(r.stopped);
    const Eigen2 e = f->eigen(r.end);
    CHECK(std::abs(r.direction.dot(e.vector2)) == Approx(1).margin(1e-6));
    // The major eigenvector is not at 90 degrees to it here: w = 0.15 x != 0.
    CHECK(std::abs(e.vector1.dot(e.vector2)) > 0.05);
  }
}
