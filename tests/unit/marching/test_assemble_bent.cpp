// Output assembly of smooth terminals (runtime/assemble.cpp): an instance with a curve is
// bent along it, the others stay rigid, and a curve index past the list is refused.
#include "runtime/assemble.h"
#include "runtime/marching/curve_bend.h"
#include "runtime/marching/curve_frame.h"
#include "runtime/marching/smooth_curves.h"

#include "tests/unit/marching/march_graphs.h"

#include <catch2/catch.hpp>
#include <tbb/task_arena.h>

#include <cmath>
#include <random>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;

namespace {

// A unit cylinder along X, sides only: `rings` rings of `around` vertices, normals radial.
Mesh xCylinder(int rings, int around) {
  Mesh m;
  for (int i = 0; i < rings; ++i)
    for (int k = 0; k < around; ++k) {
      const double a = 2 * M_PI * k / around, x = double(i) / (rings - 1);
      m.positions.insert(m.positions.end(), {float(x), float(0.5 + 0.5 * std::cos(a)), float(0.5 + 0.5 * std::sin(a))});
      m.normals.insert(m.normals.end(), {0.0f, float(std::cos(a)), float(std::sin(a))});
    }
  for (int i = 0; i + 1 < rings; ++i)
    for (int k = 0; k < around; ++k) {
      const uint32_t a = uint32_t(i * around + k), b = uint32_t(i * around + (k + 1) % around);
      m.indices.insert(m.indices.end(), {a, b, a + uint32_t(around), b, b + uint32_t(around), a + uint32_t(around)});
    }
  return m;
}

std::array<double, 16> scopeOnChord(const CurveSegment& c, double radius) {
  const Vec3 a = controlPoint(c, 0), chord = controlPoint(c, 3) - a;
  const Vec3 n(c.normal0[0], c.normal0[1], c.normal0[2]);
  const Vec3 X = chord.normalized(), Z = (n - X * X.dot(n)).normalized(), Y = Z.cross(X);
  Mat4 m = Mat4::Identity();
  m.block<3, 1>(0, 0) = chord;
  m.block<3, 1>(0, 1) = 2 * radius * Y;
  m.block<3, 1>(0, 2) = 2 * radius * Z;
  m.block<3, 1>(0, 3) = a - radius * (Y + Z);
  std::array<double, 16> out;
  Eigen::Map<Mat4>(out.data()) = m;
  return out;
}

Vec3 at(const fgsg::rt::MeshArray<float>& a, size_t v) { return Vec3(a[3 * v], a[3 * v + 1], a[3 * v + 2]); }

struct BentScene {
  InstanceList list;
  AssetLibrary library;
  std::vector<int> meshOf;
  int cylinder = -1;

  BentScene() {
    std::array<double, 16> ignored;
    cylinder = library.addGenerated("xcyl", xCylinder(9, 12), ignored);
    list.assets.push_back("xcyl");
    const fgsg::test::Graph g = fgsg::test::sphereWalk(13, 2, 1.0);
    list.curves = smoothSegments(g.nodes, g.segments);
    for (uint32_t curve : {0u, UINT32_MAX, 1u}) {
      Instance inst;
      inst.transform = scopeOnChord(list.curves[curve == UINT32_MAX ? 0 : curve], 0.03);
      inst.curve = curve;
      list.instances.push_back(inst);
    }
    std::string error;
    REQUIRE(resolveAssets(list, library, meshOf, error));
  }
};

}  // namespace

TEST_CASE("assembly bends instances with a curve and keeps the others rigid", "[assemble][bend]") {
  BentScene scene;
  const Mesh& asset = scene.library.mesh(scene.cylinder);
  const Mesh out = assembleInstances(scene.list, scene.library, scene.meshOf);
  const size_t nv = asset.vertexCount();
  REQUIRE(out.vertexCount() == 3 * nv);
  REQUIRE(out.triangleCount() == 3 * asset.triangleCount());
  CHECK(countTriangles(scene.list, scene.library, scene.meshOf) == out.triangleCount());
  double largestBend = 0;
  for (size_t i = 0; i < 3; ++i) {
    const Instance& inst = scene.list.instances[i];
    const Eigen::Map<const Mat4> m(inst.transform.data());
    const Mat3 A = m.block<3, 3>(0, 0);
    Mat3 cofactor;
    cofactor << A.col(1).cross(A.col(2)), A.col(2).cross(A.col(0)), A.col(0).cross(A.col(1));
    for (size_t v = 0; v < nv; ++v) {
      const Vec3 local = at(asset.positions, v);
      const Vec3 rigid = A * local + m.block<3, 1>(0, 3);
      Vec3 position = rigid, normal = (cofactor * at(asset.normals, v)).normalized();
      if (inst.curve != UINT32_MAX) {
        const BentPoint b = CurveBend(scene.list.curves[inst.curve], inst.transform).at(local);
        // The assembler shares a section along each ring; projecting each vertex anew
        // agrees up to rounding.
        const BentPoint r = CurveBend(scene.list.curves[inst.curve], inst.transform).atRigid(rigid);
        CHECK((at(out.positions, i * nv + v) - r.position).norm() < 1e-6);
        CHECK((at(out.normals, i * nv + v) - (r.rotation * normal).normalized()).norm() < 1e-6);
        position = b.position;
        normal = (b.rotation * normal).normalized();
        largestBend = std::max(largestBend, (b.position - rigid).norm());
      }
      INFO("instance " << i << ", vertex " << v);
      CHECK((at(out.positions, i * nv + v) - position).norm() < 1e-6);
      CHECK((at(out.normals, i * nv + v) - normal).norm() < 1e-6);
    }
  }
  // The curves sag off their chords on the sphere: the bend is seen.
  CHECK(largestBend > 1e-3);
}

TEST_CASE("assembly refuses an instance whose curve is not in the list", "[assemble][bend]") {
  BentScene scene;
  scene.list.instances[2].curve = 9;
  CHECK_THROWS_WITH(assembleInstances(scene.list, scene.library, scene.meshOf),
                    "instance 2 follows curve 9, but the instance list has 2 curves");
  CHECK_THROWS_WITH(countTriangles(scene.list, scene.library, scene.meshOf),
                    "instance 2 follows curve 9, but the instance list has 2 curves");
}

TEST_CASE("bent assembly bytes do not depend on the number of threads", "[assemble][bend]") {
  // Enough bark on enough curves for many blocks, scopes of several radii and rolls, some
  // instances rigid and one flattened.
  BentScene scene;
  const fgsg::test::Graph g = fgsg::test::sphereWalk(5, 40, 1.0);
  scene.list.curves = smoothSegments(g.nodes, g.segments);
  scene.list.assets.push_back("bark");
  std::string error;
  REQUIRE(resolveAssets(scene.list, scene.library, scene.meshOf, error));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  scene.list.instances.clear();
  for (uint32_t i = 0; i < 600; ++i) {
    Instance inst;
    inst.asset = i % 2;
    inst.curve = i % 9 == 0 ? UINT32_MAX : uint32_t(i % scene.list.curves.size());
    inst.transform = scopeOnChord(scene.list.curves[i % scene.list.curves.size()], 0.01 + 0.05 * u(rng));
    if (i == 17) std::fill_n(inst.transform.begin() + 4, 4, 0.0);  // a flattened Y column
    inst.color = {float(u(rng)), 0.5f, 0.25f};
    scene.list.instances.push_back(inst);
  }
  const Mesh parallel = assembleInstances(scene.list, scene.library, scene.meshOf);
  Mesh serial;
  tbb::task_arena(1).execute([&] { serial = assembleInstances(scene.list, scene.library, scene.meshOf); });
  CHECK(parallel.positions == serial.positions);
  CHECK(parallel.normals == serial.normals);
  CHECK(parallel.colors == serial.colors);
  CHECK(parallel.texcoords == serial.texcoords);
  CHECK(parallel.indices == serial.indices);
  CHECK(countTriangles(scene.list, scene.library, scene.meshOf) == parallel.triangleCount());
  // Again into the mesh just assembled (its memory reused): the same arrays.
  Mesh reused = serial;
  tbb::task_arena(2).execute([&] { assembleInstances(scene.list, scene.library, scene.meshOf, reused); });
  CHECK(reused.positions == parallel.positions);
  CHECK(reused.normals == parallel.normals);
  CHECK(reused.indices == parallel.indices);
}
