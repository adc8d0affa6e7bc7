// Singularities and smoothing (FGSG §4.2, Fig. 7): Laplacian smoothing removes the
// singularities of a random field until the Poincare-Hopf index sum is all that is left
// to account for — 2 (doubled: 4) on a sphere, 0 on a torus — for vector and line fields;
// analytic fields put their singular points where they belong.
#include "runtime/field/singularities.h"
#include "runtime/field/smooth.h"

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

struct Lcg {
  uint64_t s;
  explicit Lcg(uint64_t seed) : s(seed) {}
  double operator()() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return (s >> 11) * (1.0 / 9007199254740992.0) * 2 - 1;
  }
};

TangentField randomField(std::shared_ptr<const TangentFrames> frames, FieldType type,
                         uint64_t seed) {
  TangentField field(frames, type);
  Lcg rnd(seed);
  for (size_t v = 0; v < field.vertexCount(); ++v) {
    if (type == FieldType::Vector) {
      field.setVertexVector(int(v), Vec2(rnd(), rnd()));
    } else {
      const double a = rnd(), b = rnd(), c = rnd();
      Mat2 t;
      t << a, b, b, c;
      field.setVertexTensor(int(v), t);
    }
  }
  return field;
}

}  // namespace

TEST_CASE("smoothed random fields on a sphere have index sum 2 (doubled 4)", "[field]") {
  const SurfaceMesh m = testing::icosphere(3, 1.0);
  auto frames = TangentFrames::make(m);
  for (auto type : {FieldType::Vector, FieldType::Tensor})
    for (uint64_t seed : {1, 2, 3}) {
      TangentField field = randomField(frames, type, seed);
      const size_t before = field.degeneracies().size();
      smooth(field, 300);
      const auto& d = field.degeneracies();
      INFO((type == FieldType::Vector ? "vector" : "tensor") << " seed " << seed << ": "
           << before << " singularities before smoothing, " << d.size() << " after");
      CHECK(indexSumTimesTwo(d) == 4);
      CHECK(d.size() < before / 10);
    }
}

TEST_CASE("smoothed random fields on a torus have index sum 0", "[field]") {
  const SurfaceMesh m = testing::torus(60, 24, 2.0, 0.7);
  auto frames = TangentFrames::make(m);
  for (auto type : {FieldType::Vector, FieldType::Tensor})
    for (uint64_t seed : {4, 5}) {
      TangentField field = randomField(frames, type, seed);
      smooth(field, 300);
      INFO((type == FieldType::Vector ? "vector" : "tensor") << " seed " << seed << ": "
           << field.degeneracies().size() << " singularities");
      CHECK(indexSumTimesTwo(field.degeneracies()) == 0);
    }
}

TEST_CASE("the index sum holds for unsmoothed random fields too", "[field]") {
  // Discrete Poincare-Hopf: every face winding is counted in its own frame, and the sum
  // over a closed mesh is still chi as long as no edge joins opposite values.
  const SurfaceMesh m = testing::icosphere(2, 1.0);
  auto frames = TangentFrames::make(m);
  TangentField field = randomField(frames, FieldType::Vector, 9);
  smooth(field, 3);
  CHECK(indexSumTimesTwo(field.degeneracies()) == 4);
}

TEST_CASE("smoothing keeps a parallel field and locked vertices, and damps noise",
          "[field]") {
  const SurfaceMesh m = testing::flatGrid(10, 10, 0, 0, 1, 1, 0.3);
  auto frames = TangentFrames::make(m);
  TangentField field(frames, FieldType::Tensor);
  Mat3 T = Mat3::Zero();
  T(0, 0) = 2;
  T(1, 1) = -1;
  for (size_t v = 0; v < m.vertexCount(); ++v) field.setVertexTensorWorld(int(v), T);
  smooth(field, 50);
  for (size_t v = 0; v < m.vertexCount(); ++v)
    CHECK((field.vertexTensorWorld(int(v)) - T).norm() < 1e-12);

  TangentField noisy = randomField(frames, FieldType::Vector, 7);
  std::vector<uint8_t> locked(m.vertexCount(), 0);
  locked[17] = 1;
  const Vec2 kept = noisy.vertexVector(17);
  auto roughness = [&](const TangentField& f) {
    double sum = 0;
    for (int i = 0; i < int(m.vertexCount()); ++i)
      for (int r = frames->neighbourBegin(i); r < frames->neighbourEnd(i); ++r)
        sum += (rotate(frames->neighbourToVertex(r), f.vertexVector(frames->neighbour(r))) -
                f.vertexVector(i)).squaredNorm();
    return sum;
  };
  const double before = roughness(noisy);
  SmoothOptions options;
  options.locked = &locked;
  smooth(noisy, 10, options);
  CHECK(noisy.vertexVector(17) == kept);
  CHECK(roughness(noisy) < 0.1 * before);
}

TEST_CASE("analytic fields: sources, centres, saddles and a wedge where they belong",
          "[field]") {
  const SurfaceMesh m = testing::flatGrid(12, 12, -1.03, -0.97, 2, 2, 0.2);
  auto frames = TangentFrames::make(m);
  // v(x, y) = A (x, y): a node, a centre, a focus or a saddle at the origin.
  struct Case {
    double a, b, c, d;
    Degeneracy::Kind kind;
    int indexTimesTwo;
  };
  const Case cases[] = {{1, 0, 0, 2, Degeneracy::Node, 2},
                        {-1, 0, 0, -1, Degeneracy::Node, 2},
                        {0, -1, 1, 0, Degeneracy::Centre, 2},
                        {0.5, -1, 1, 0.5, Degeneracy::Focus, 2},
                        {1, 0, 0, -1, Degeneracy::Saddle, -2}};
  for (const Case& k : cases) {
    TangentField field(frames, FieldType::Vector);
    for (size_t v = 0; v < m.vertexCount(); ++v) {
      const Vec3& p = m.vertices[v];
      const Vec3 value(k.a * p.x() + k.b * p.y(), k.c * p.x() + k.d * p.y(), 0);
      field.setVertexVectorWorld(int(v), value);
    }
    const auto& d = field.degeneracies();
    REQUIRE(d.size() == 1);
    CHECK(d[0].kind == k.kind);
    CHECK(d[0].indexTimesTwo == k.indexTimesTwo);
    CHECK(d[0].at.position(m).norm() < 1e-9);  // a linear field's zero is exact
    CHECK(faceIndexTimesTwo(field, d[0].face) == k.indexTimesTwo);
  }
  // The tensor [[x, y], [y, -x]] is a wedge at the origin; [[x, -y], [-y, -x]] a trisector.
  for (int sign : {1, -1}) {
    TangentField field(frames, FieldType::Tensor);
    for (size_t v = 0; v < m.vertexCount(); ++v) {
      const Vec3& p = m.vertices[v];
      Mat3 t = Mat3::Zero();
      t(0, 0) = p.x();
      t(1, 1) = -p.x();
      t(0, 1) = t(1, 0) = sign * p.y();
      field.setVertexTensorWorld(int(v), t + 0.5 * Mat3::Identity());
    }
    const auto& d = field.degeneracies();
    REQUIRE(d.size() == 1);
    CHECK(d[0].kind == (sign > 0 ? Degeneracy::Wedge : Degeneracy::Trisector));
    CHECK(d[0].indexTimesTwo == sign);
    CHECK(d[0].at.position(m).norm() < 1e-9);
  }
}

TEST_CASE("a source exactly on a vertex is found at the vertex", "[field]") {
  const SurfaceMesh m = testing::flatGrid(10, 10, -1, -1, 2, 2, 0);  // a vertex at 0
  auto frames = TangentFrames::make(m);
  TangentField field(frames, FieldType::Vector);
  for (size_t v = 0; v < m.vertexCount(); ++v) field.setVertexVectorWorld(int(v), m.vertices[v]);
  const auto& d = field.degeneracies();
  REQUIRE(d.size() == 1);
  CHECK(d[0].kind == Degeneracy::Node);
  CHECK(d[0].indexTimesTwo == 2);
  CHECK(d[0].at.position(m).norm() < 1e-12);
  // Editing drops the cache: with a value at the vertex, the source moves into a face.
  field.setVertexVectorWorld(60, Vec3(0.01, 0.02, 0));
  REQUIRE(field.degeneracies().size() == 1);
  CHECK(field.degeneracies()[0].indexTimesTwo == 2);
  CHECK(field.degeneracies()[0].at.bary.maxCoeff() < 1);
  CHECK(field.degeneracies()[0].at.position(m).norm() < 0.2);
}
