// Field design with elements (FGSG §4.2, eq. 3): heat-method geodesic distances and polar
// angles, and each element kind producing exactly the singularity it stands for.
#include "runtime/field/design.h"
#include "runtime/field/singularities.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::field;

namespace fgsg::rt::field::testing {
SurfaceMesh flatGrid(int nx, int ny, double x0, double y0, double w, double h, double jitter);
SurfaceMesh icosphere(int subdivisions, double radius);
SurfaceMesh torus(int nu, int nv, double R, double r);
}  // namespace fgsg::rt::field::testing

namespace {

constexpr double kPi = 3.14159265358979323846;

// The surface point nearest to `target` among face centres and corners (good enough to
// place an element "there").
SurfacePoint pointNear(const SurfaceMesh& m, const Vec3& target) {
  SurfacePoint best;
  double bestDist = INFINITY;
  for (size_t f = 0; f < m.faceCount(); ++f) {
    SurfacePoint p;
    p.face = int(f);
    p.bary = Vec3(0.45, 0.3, 0.25);  // off-centre: no symmetry coincidences
    const double d = (p.position(m) - target).norm();
    if (d < bestDist) bestDist = d, best = p;
  }
  return best;
}

struct Flat {
  SurfaceMesh mesh = testing::flatGrid(30, 30, -1, -1, 2, 2, 0.3);
  std::shared_ptr<const TangentFrames> frames = TangentFrames::make(mesh);
  FieldDesigner designer{frames};
};

Flat& flat() {
  static Flat f;
  return f;
}

}  // namespace

TEST_CASE("heat-method distances on a sphere follow great circles", "[field]") {
  const SurfaceMesh m = testing::icosphere(4, 2.0);
  auto frames = TangentFrames::make(m);
  const HeatGeodesics geo(frames);
  REQUIRE(geo.ok());
  const SurfacePoint source = pointNear(m, Vec3(0, 0, 2));
  const Vec3 s = source.position(m).normalized();
  const std::vector<double> rho = geo.distance(source);
  double worst = 0;
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const double exact = 2 * std::acos(std::clamp(m.vertices[v].normalized().dot(s), -1.0, 1.0));
    worst = std::max(worst, std::abs(rho[v] - exact));
  }
  INFO("largest error " << worst << " on a sphere of radius 2 (half circumference 6.28)");
  CHECK(worst < 0.05);
}

TEST_CASE("polar coordinates around a point on a flat mesh are the planar ones", "[field]") {
  // Boundary vertices included: the heat method averages two boundary conditions there.
  Flat& f = flat();
  const SurfacePoint source = pointNear(f.mesh, Vec3(0.1, -0.05, 0));
  const Vec3 c = source.position(f.mesh);
  const Vec3 axis(std::cos(0.4), std::sin(0.4), 0);  // theta = 0 along this
  for (auto method : {PolarMethod::Heat, PolarMethod::ExponentialMap}) {
    const FieldDesigner designer(f.frames, method);
    const PolarMap map = designer.polarMap(source, axis);
    double worstAngle = 0, worstDist = 0, worstRef = 0;
    for (size_t v = 0; v < f.mesh.vertexCount(); ++v) {
      const Vec3 d = f.mesh.vertices[v] - c;
      const double theta = std::atan2(d.y(), d.x()) - 0.4;
      const Frame& fr = f.frames->vertexFrame(int(v));
      // The reference carried to v stays the axis (flat: parallel transport is trivial).
      const Vec3 ref = fr.toWorld(Vec2(map.reference[v].real(), map.reference[v].imag()));
      worstRef = std::max(worstRef, (ref - axis).norm());
      worstAngle = std::max(worstAngle, std::abs(std::arg(map.angle[v] * std::polar(1.0, -theta))));
      worstDist = std::max(worstDist, std::abs(map.distance[v] - d.norm()));
    }
    INFO((method == PolarMethod::Heat ? "heat" : "exponential map")
         << ": angle error " << worstAngle * 180 / kPi << " degrees, distance error " << worstDist);
    CHECK(worstRef < 1e-9);
    CHECK(worstAngle < 1e-9);  // both are exact on a flat mesh (distances: see below)
    CHECK(worstDist < (method == PolarMethod::Heat ? 0.04 : 1e-12));
  }
}

TEST_CASE("polar angles on a sphere: heat everywhere, exponential map near", "[field]") {
  const SurfaceMesh m = testing::icosphere(4, 1.0);
  auto frames = TangentFrames::make(m);
  SurfacePoint source;
  source.face = 17;
  source.bary = Vec3(0.45, 0.3, 0.25);
  const Vec3 s = source.position(m).normalized();
  const Vec3 ref = frames->faceFrame(17).e1;
  const Vec3 r0 = (ref - ref.dot(s) * s).normalized();
  for (auto method : {PolarMethod::Heat, PolarMethod::ExponentialMap}) {
    const FieldDesigner designer(frames, method);
    const PolarMap map = designer.polarMap(source, ref);
    // Within 1 radius the exponential map is good; the heat method up to 0.85 pi.
    const double reach = method == PolarMethod::Heat ? 0.85 * kPi : 1.0;
    double worstAngle = 0, worstDist = 0;
    for (size_t v = 0; v < m.vertexCount(); ++v) {
      const Vec3 p = m.vertices[v].normalized();
      const double rho = std::acos(std::clamp(p.dot(s), -1.0, 1.0));
      if (rho < 1e-9 || rho > reach) continue;
      const Vec3 leaving = (p - p.dot(s) * s).normalized();  // the geodesic at the source
      const double theta = std::atan2(s.cross(r0).dot(leaving), r0.dot(leaving));
      worstAngle = std::max(worstAngle, std::abs(std::arg(map.angle[v] * std::polar(1.0, -theta))));
      worstDist = std::max(worstDist, std::abs(map.distance[v] - rho));
    }
    INFO((method == PolarMethod::Heat ? "heat" : "exponential map")
         << ": angle error " << worstAngle * 180 / kPi << " degrees, distance error " << worstDist);
    CHECK(worstAngle < (method == PolarMethod::Heat ? 1.0 : 4.0) * kPi / 180);
    CHECK(worstDist < 0.02);
  }
}

TEST_CASE("a regular element gives a parallel field that decays with distance", "[field]") {
  Flat& f = flat();
  DesignElement e;
  e.at = pointNear(f.mesh, Vec3(0, 0, 0));
  e.direction = Vec3(1, 1, 0);
  e.decay = 2;
  e.strength = 3;
  for (auto type : {FieldType::Vector, FieldType::Tensor}) {
    TangentField field(f.frames, type);
    std::string error;
    REQUIRE(f.designer.design(type, {e}, field, error));
    const Vec3 c = e.at.position(f.mesh);
    for (size_t v = 0; v < f.mesh.vertexCount(); v += 13) {
      SurfacePoint p;
      p.face = f.mesh.vertexFace[v];
      p.bary = Vec3::Zero();
      p.bary[f.mesh.cornerOf(p.face, int(v))] = 1;
      const Eigen2 eig = field.eigen(p);
      CHECK(std::abs(std::abs(eig.vector1.dot(Vec3(1, 1, 0).normalized())) - 1) < 1e-4);
      const double want = 3 * std::exp(-2 * (f.mesh.vertices[v] - c).norm());
      CHECK(eig.value1 == Approx(want).epsilon(0.1).margin(2e-3));
    }
    CHECK(field.degeneracies().empty());
  }
}

TEST_CASE("each singular element makes one degenerate point of its index", "[field]") {
  Flat& f = flat();
  struct Case {
    FieldType type;
    ElementKind kind;
    double strength;
    Degeneracy::Kind want;
    int indexTimesTwo;
  };
  const Case cases[] = {
      {FieldType::Tensor, ElementKind::Wedge, 1, Degeneracy::Wedge, 1},
      {FieldType::Tensor, ElementKind::Trisector, 1, Degeneracy::Trisector, -1},
      {FieldType::Vector, ElementKind::Node, 1, Degeneracy::Node, 2},
      {FieldType::Vector, ElementKind::Node, -1, Degeneracy::Node, 2},  // a sink
      {FieldType::Vector, ElementKind::Centre, 1, Degeneracy::Centre, 2},
      {FieldType::Vector, ElementKind::Saddle, 1, Degeneracy::Saddle, -2},
  };
  for (const Case& k : cases) {
    DesignElement e;
    e.kind = k.kind;
    e.at = pointNear(f.mesh, Vec3(0.23, -0.17, 0));
    e.strength = k.strength;
    e.decay = 1.5;
    TangentField field(f.frames, k.type);
    std::string error;
    REQUIRE(f.designer.design(k.type, {e}, field, error));
    const auto& d = field.degeneracies();
    INFO(elementKindName(k.kind) << " strength " << k.strength);
    REQUIRE(d.size() == 1);
    CHECK(d[0].kind == k.want);
    CHECK(d[0].indexTimesTwo == k.indexTimesTwo);
    CHECK(d[0].face == e.at.face);
    CHECK((d[0].at.position(f.mesh) - e.at.position(f.mesh)).norm() < 0.5 * f.mesh.meanEdgeLength);
    CHECK(field.degeneraciesIn(e.at.face).size() == 1);
    CHECK(field.degeneraciesIn((e.at.face + 1) % int(f.mesh.faceCount())).empty());
  }
}

TEST_CASE("designing with the exponential map gives the same singularities", "[field]") {
  Flat& f = flat();
  const FieldDesigner designer(f.frames, PolarMethod::ExponentialMap);
  DesignElement e;
  e.kind = ElementKind::Trisector;
  e.at = pointNear(f.mesh, Vec3(0.23, -0.17, 0));
  e.decay = 30;  // reaches ln(1e12) / 30 = 0.92: vertices beyond stay zero
  TangentField field(f.frames, FieldType::Tensor);
  std::string error;
  REQUIRE(designer.design(FieldType::Tensor, {e}, field, error));
  REQUIRE(field.degeneracies().size() == 1);
  CHECK(field.degeneracies()[0].kind == Degeneracy::Trisector);
  CHECK(field.degeneracies()[0].face == e.at.face);
  CHECK(field.vertexTensor(0).norm() == 0);  // the corner at (-1, -1), 1.48 away
  // Within reach its directions are the heat designer's (both exact on a flat mesh).
  TangentField heat(f.frames, FieldType::Tensor);
  REQUIRE(f.designer.design(FieldType::Tensor, {e}, heat, error));
  for (size_t v = 0; v < f.mesh.vertexCount(); ++v)
    if (field.vertexTensor(int(v)).norm() > 0 && heat.vertexTensor(int(v)).norm() > 0) {
      const double turn = eigenOf(field.vertexTensor(int(v))).angle -
                          eigenOf(heat.vertexTensor(int(v))).angle;
      CHECK(std::abs(std::sin(turn)) < 1e-9);
    }
}

TEST_CASE("a tensor node, centre and saddle carry index +1, +1, -1", "[field]") {
  // In a piecewise-linear tensor field an index-1 point splits into two half-index ones.
  Flat& f = flat();
  const std::pair<ElementKind, int> cases[] = {
      {ElementKind::Node, 2}, {ElementKind::Centre, 2}, {ElementKind::Saddle, -2}};
  for (auto [kind, sum] : cases) {
    DesignElement e;
    e.kind = kind;
    e.at = pointNear(f.mesh, Vec3(-0.3, 0.2, 0));
    TangentField field(f.frames, FieldType::Tensor);
    std::string error;
    REQUIRE(f.designer.design(FieldType::Tensor, {e}, field, error));
    CHECK(indexSumTimesTwo(field.degeneracies()) == sum);
    for (const Degeneracy& d : field.degeneracies())
      CHECK((d.at.position(f.mesh) - e.at.position(f.mesh)).norm() < 2 * f.mesh.meanEdgeLength);
  }
}

TEST_CASE("an element on a vertex makes that vertex the degenerate point", "[field]") {
  Flat& f = flat();
  DesignElement e;
  e.kind = ElementKind::Wedge;
  const int v = 15 * 31 + 15;  // the grid's middle vertex
  e.at.face = f.mesh.vertexFace[v];
  e.at.bary = Vec3::Zero();
  e.at.bary[f.mesh.cornerOf(e.at.face, v)] = 1;
  TangentField field(f.frames, FieldType::Tensor);
  std::string error;
  REQUIRE(f.designer.design(FieldType::Tensor, {e}, field, error));
  CHECK(field.vertexTensor(v).norm() == 0);
  const auto& d = field.degeneracies();
  REQUIRE(d.size() == 1);
  CHECK(d[0].kind == Degeneracy::Wedge);
  CHECK((d[0].at.position(f.mesh) - f.mesh.vertices[v]).norm() < 1e-12);
}

TEST_CASE("a wedge on a sphere: one +1/2 point near it, indices summing to chi", "[field]") {
  const SurfaceMesh m = testing::icosphere(4, 1.0);
  auto frames = TangentFrames::make(m);
  FieldDesigner designer(frames);
  DesignElement e;
  e.kind = ElementKind::Wedge;
  e.at = pointNear(m, Vec3(0.3, 0.2, 0.9).normalized());
  e.decay = 1;
  TangentField field(frames, FieldType::Tensor);
  std::string error;
  REQUIRE(designer.design(FieldType::Tensor, {e}, field, error));
  const Vec3 c = e.at.position(m);
  int nearby = 0;
  for (const Degeneracy& d : field.degeneracies())
    if ((d.at.position(m) - c).norm() < 0.5) {
      ++nearby;
      CHECK(d.kind == Degeneracy::Wedge);
      CHECK((d.at.position(m) - c).norm() < m.meanEdgeLength);
    }
  CHECK(nearby == 1);
  CHECK(indexSumTimesTwo(field.degeneracies()) == 4);  // line-field indices sum to chi = 2
}

TEST_CASE("several elements add up, a designed field on a torus has index sum 0", "[field]") {
  const SurfaceMesh m = testing::torus(48, 24, 2.0, 0.7);
  auto frames = TangentFrames::make(m);
  FieldDesigner designer(frames);
  std::vector<DesignElement> elements(3);
  elements[0].at = pointNear(m, Vec3(2.7, 0, 0));
  elements[0].direction = Vec3(0, 1, 0);
  elements[1].kind = ElementKind::Wedge;
  elements[1].at = pointNear(m, Vec3(-2.7, 0.3, 0));
  elements[2].kind = ElementKind::Trisector;
  elements[2].at = pointNear(m, Vec3(0, 2, 0.7));
  for (auto& e : elements) e.decay = 0.8;
  TangentField field(frames, FieldType::Tensor);
  std::string error;
  REQUIRE(designer.design(FieldType::Tensor, elements, field, error));
  CHECK(indexSumTimesTwo(field.degeneracies()) == 0);
  // The sum of the separately designed fields.
  TangentField sum(frames, FieldType::Tensor);
  for (auto& e : elements) REQUIRE(designer.add(e, sum, error));
  for (size_t v = 0; v < m.vertexCount(); ++v)
    CHECK((sum.vertexTensor(int(v)) - field.vertexTensor(int(v))).norm() < 1e-12);
}

TEST_CASE("design rejects elements that do not fit", "[field]") {
  Flat& f = flat();
  TangentField field(f.frames, FieldType::Vector);
  std::string error;
  DesignElement e;
  e.kind = ElementKind::Wedge;
  e.at.face = 0;
  CHECK_FALSE(f.designer.add(e, field, error));
  CHECK(error == "wedge element: wedges and trisectors are tensor-field elements");
  e.kind = ElementKind::Node;
  e.at.face = int(f.mesh.faceCount());
  CHECK_FALSE(f.designer.add(e, field, error));
  CHECK(error.find("is not on the surface") != std::string::npos);
  e.at.face = 0;
  e.decay = -1;
  CHECK_FALSE(f.designer.add(e, field, error));
  e.decay = 1;
  e.at.bary = Vec3(0.5, 0.6, 0);
  CHECK_FALSE(f.designer.add(e, field, error));
  CHECK(error == "node element: barycentric coordinates must be >= 0 and sum to 1");
}
