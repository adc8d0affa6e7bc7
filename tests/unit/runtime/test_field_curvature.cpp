// The curvature tensor field (FGSG §4.3 (d), Fig. 11): principal curvatures of a sphere,
// a cylinder (and the direction of the larger one) and the sign pattern of a torus.
#include "runtime/field/curvature.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::field;

namespace fgsg::rt::field::testing {
SurfaceMesh icosphere(int subdivisions, double radius);
SurfaceMesh torus(int nu, int nv, double R, double r);
SurfaceMesh cylinder(int nu, int nz, double r, double h);
}  // namespace fgsg::rt::field::testing

namespace {

constexpr double kWithin = 0.05;  // 5 %

SurfacePoint atVertex(const SurfaceMesh& m, int v) {
  SurfacePoint p;
  p.face = m.vertexFace[v];
  p.bary = Vec3::Zero();
  p.bary[m.cornerOf(p.face, v)] = 1;
  return p;
}

}  // namespace

TEST_CASE("a sphere of radius r has both principal curvatures 1/r", "[field]") {
  const double r = 2.5;
  const SurfaceMesh m = testing::icosphere(4, r);
  const TangentField k = curvatureTensor(TangentFrames::make(m));
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const Curvatures c = curvaturesAt(k, atVertex(m, int(v)));
    CHECK(c.max == Approx(1 / r).epsilon(kWithin));
    CHECK(c.min == Approx(1 / r).epsilon(kWithin));
    CHECK(c.mean == Approx(1 / r).epsilon(kWithin));
    CHECK(c.gauss == Approx(1 / (r * r)).epsilon(2 * kWithin));
  }
  // Inside faces too.
  SurfacePoint p;
  p.face = 100;
  CHECK(curvaturesAt(k, p).max == Approx(1 / r).epsilon(kWithin));
}

TEST_CASE("a cylinder curves 1/r around its axis and not along it", "[field]") {
  const double r = 0.8;
  const SurfaceMesh m = testing::cylinder(48, 30, r, 4.0);
  const TangentField k = curvatureTensor(TangentFrames::make(m));
  int checked = 0;
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    if (m.boundaryVertex[v]) continue;
    ++checked;
    const SurfacePoint p = atVertex(m, int(v));
    const Curvatures c = curvaturesAt(k, p);
    CHECK(c.max == Approx(1 / r).epsilon(kWithin));
    CHECK(std::abs(c.min) < kWithin / r);
    // The major direction goes around the axis, the minor along it.
    const Eigen2 e = k.eigen(p);
    CHECK(std::abs(e.vector1.z()) < 0.05);
    CHECK(std::abs(e.vector2.z()) > 0.99);
  }
  CHECK(checked > 1000);
}

TEST_CASE("a torus has negative Gaussian curvature inside, positive outside", "[field]") {
  const double R = 2, r = 0.7;
  const SurfaceMesh m = testing::torus(96, 40, R, r);
  const TangentField k = curvatureTensor(TangentFrames::make(m));
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const Vec3& p = m.vertices[v];
    const double fromAxis = std::hypot(p.x(), p.y());
    // K = cos(v) / (r (R + r cos v)); |K| is tiny on the top and bottom circles.
    const double cosv = (fromAxis - R) / r;
    const double K = cosv / (r * (R + r * cosv));
    const Curvatures c = curvaturesAt(k, atVertex(m, int(v)));
    if (std::abs(cosv) > 0.3) CHECK((c.gauss > 0) == (K > 0));
    if (std::abs(cosv) > 0.3) CHECK(c.gauss == Approx(K).epsilon(0.1));
    // Around the tube the curvature is 1/r everywhere.
    CHECK(c.max == Approx(1 / r).epsilon(kWithin));
  }
}
