// Random marches on real meshes (tests/data/meshes, see tests/data/README.md) over box-
// projection atlases: hundreds of distorted charts, corners where many meet, and charts
// with slits narrower than a texel, where no indirection texel exists and the mesh's own
// neighbour carries the march across.
#include "box_projection_atlas.h"
#include "march_fixtures.h"

#include "runtime/surface/load_surface.h"

#include <filesystem>
#include <random>

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using namespace fgsg::rt::marching::testing;

namespace {

surface::SurfaceMesh loadTestMesh(const std::string& name) {
  const auto path = std::filesystem::path(FGSG_SOURCE_DIR) / "tests" / "data" / "meshes" / name;
  if (!std::filesystem::exists(path)) FAIL("tests/data/meshes/" << name << " is missing: run scripts/fetch-test-meshes.sh");
  surface::SurfaceMesh mesh;
  std::string error;
  INFO(error);
  REQUIRE(surface::loadSurface(path.string(), mesh, error));
  return mesh;
}

// Whether p lies on an edge of its face that has no neighbour.
bool onOwnBoundary(const surface::SurfaceMesh& mesh, const surface::SurfacePoint& p) {
  for (int k = 0; k < 3; ++k)
    if (mesh.neighbours[p.face][k] < 0 && p.bary[(k + 2) % 3] == 0) return true;
  return false;
}

void marchAtRandom(const std::string& name, int count, bool closed, uint64_t seed) {
  INFO(name);
  const surface::SurfaceMesh mesh = loadTestMesh(name);
  ChartedMesh c{mesh, boxProjectionAtlas(mesh, 1024)};
  const auto s = prepared(c);
  const surface::SurfaceLocator locator(s->mesh());
  const double diagonal = (mesh.boundsMax - mesh.boundsMin).norm();
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> face(0, int(mesh.faceCount()) - 1);
  std::uniform_real_distribution<double> unit01(0, 1), angle(0, 2 * kPi);
  int ends[6] = {}, pointerJumps = 0, adjacencyJumps = 0;
  for (int k = 0; k < count; ++k) {
    const int f = face(rng);
    double a = unit01(rng), b = unit01(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const Vec3 n = mesh.faceNormals[f], e = n.unitOrthogonal(), e2 = n.cross(e);
    const double phi = angle(rng);
    const MarchPoint from = s->place({f, Vec3(1 - a - b, a, b)}, std::cos(phi) * e + std::sin(phi) * e2);
    // Surface lengths up to a sixth of the diagonal, image lengths up to 100 texels.
    const LengthUnit unit = k % 2 ? LengthUnit::Image : LengthUnit::Surface;
    const double length = unit01(rng) * (unit == LengthUnit::Image ? 100 : diagonal / 6);
    MarchPoint to;
    MarchTrace trace;
    const bool arrived = s->march(from, length, unit, to, &trace);
    INFO("march " << k << " from face " << f << " length " << length << (k % 2 ? " texels" : ""));
    REQUIRE(consistent(*s, to));
    double distance = 1;
    locator.closestPoint(s->position(to), &distance);
    REQUIRE(distance < 1e-9 * diagonal);
    if (arrived && unit == LengthUnit::Surface)
      REQUIRE(std::abs((s->position(to) - s->position(from)).norm() - length) <= 1e-9 * length);
    if (trace.end == MarchEnd::Boundary) REQUIRE(onOwnBoundary(mesh, to.at));
    ++ends[int(trace.end)];
    pointerJumps += trace.pointerJumps;
    adjacencyJumps += trace.adjacencyJumps;
  }
  // A surface length may exceed what a path looping round an ear or a finger reaches
  // (0.57 % on the armadillo, 0.15 % on the bunny).
  CHECK(ends[int(MarchEnd::PathTooLong)] < count / 100);
  CHECK(ends[int(MarchEnd::NoProgress)] == 0);
  CHECK(ends[int(MarchEnd::FaceLimit)] == 0);
  CHECK(ends[int(MarchEnd::Refused)] == 0);
  if (closed) CHECK(ends[int(MarchEnd::Boundary)] == 0);
  // The pointers carry most jumps; the mesh's neighbour takes over where a slit in a
  // chart left no indirection texel, or the pointer's chart is not the one across.
  CHECK(pointerJumps > 5 * adjacencyJumps);
  CHECK(pointerJumps > count / 2);
}

}  // namespace

TEST_CASE("100 000 random marches on the bunny end on the surface", "[marching][march][realmesh]") {
  marchAtRandom("bunny00.off", 100000, true, 1);
}

TEST_CASE("random marches on the armadillo, the elephant and the dragon end on the surface",
          "[marching][march][realmesh]") {
  marchAtRandom("armadillo.off", 20000, true, 2);
  marchAtRandom("elephant.off", 20000, true, 3);
  marchAtRandom("ChineseDragon-10kv.off", 20000, false, 4);  // six boundary edges
}
