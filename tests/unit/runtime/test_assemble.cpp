// Assembling instances into one world-space mesh: transforms, cofactor normals,
// degenerate triangles, colours, and thread-count independence.
#include "runtime/assemble.h"
#include "runtime/output/time_budget.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace fgsg::rt;

namespace {

std::array<double, 16> toArray(const Eigen::Matrix4d& m) {
  std::array<double, 16> a;
  Eigen::Map<Eigen::Matrix4d>(a.data()) = m;  // column-major, as Instance::transform
  return a;
}

std::array<double, 16> scaleTranslate(Eigen::Vector3d s, Eigen::Vector3d t) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = s.asDiagonal();
  m.block<3, 1>(0, 3) = t;
  return toArray(m);
}

struct Scene {
  InstanceList list;
  AssetLibrary library;
  std::vector<int> meshOf;

  void add(const std::string& asset, const std::array<double, 16>& transform,
           std::array<float, 3> color = {0.8f, 0.8f, 0.8f}) {
    uint32_t index = 0;
    while (index < list.assets.size() && list.assets[index] != asset) ++index;
    if (index == list.assets.size()) list.assets.push_back(asset);
    Instance inst;
    inst.asset = index;
    inst.transform = transform;
    inst.color = color;
    list.instances.push_back(inst);
  }
  Mesh assemble() {
    std::string error;
    REQUIRE(resolveAssets(list, library, meshOf, error));
    return assembleInstances(list, library, meshOf);
  }
};

Eigen::Vector3d vec(const fgsg::rt::MeshArray<float>& a, size_t v) { return {a[3 * v], a[3 * v + 1], a[3 * v + 2]}; }

Eigen::Vector3d faceNormal(const Mesh& m, size_t t) {
  const auto a = vec(m.positions, m.indices[3 * t]), b = vec(m.positions, m.indices[3 * t + 1]),
             c = vec(m.positions, m.indices[3 * t + 2]);
  return (b - a).cross(c - a);
}

double signedVolume(const Mesh& m) {
  double vol = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    vol += vec(m.positions, m.indices[3 * t]).dot(faceNormal(m, t)) / 6.0;
  return vol;
}

// For flat-faced assets every vertex normal equals its face's normal.
void checkFlatNormals(const Mesh& m) {
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const Eigen::Vector3d n = faceNormal(m, t).normalized();
    for (int k = 0; k < 3; ++k) CHECK(vec(m.normals, m.indices[3 * t + k]).dot(n) == Approx(1.0).epsilon(1e-5));
  }
}

}  // namespace

TEST_CASE("two cubes assemble to known bounds", "[assemble]") {
  Scene s;
  s.add("cube", scaleTranslate({1, 1, 1}, {0, 0, 0}), {1, 0, 0});
  s.add("cube", scaleTranslate({1, 2, 3}, {2, 0, 0}), {0, 0, 1});
  const Mesh m = s.assemble();
  CHECK(m.triangleCount() == 24);
  CHECK(m.vertexCount() == 48);
  CHECK(m.boundsMin() == std::array<float, 3>{0, 0, 0});
  CHECK(m.boundsMax() == std::array<float, 3>{3, 2, 3});
  CHECK(signedVolume(m) == Approx(1 + 6));
  checkFlatNormals(m);
  REQUIRE(m.colors.size() == m.positions.size());
  CHECK(vec(m.colors, 0) == Eigen::Vector3d(1, 0, 0));  // instances keep list order
  CHECK(vec(m.colors, 47) == Eigen::Vector3d(0, 0, 1));
  CHECK(countTriangles(s.list, s.library, s.meshOf) == 24);
}

TEST_CASE("a flattened cube keeps only its top and bottom", "[assemble]") {
  Scene s;
  s.add("cube", scaleTranslate({2, 3, 0}, {1, 1, 5}));
  const Mesh m = s.assemble();
  // The four sides collapse to zero area; +Z and -Z keep two triangles each.
  CHECK(m.triangleCount() == 4);
  CHECK(m.vertexCount() == 8);  // the vertices only the dropped sides used are gone
  CHECK(countTriangles(s.list, s.library, s.meshOf) == 4);
  CHECK(m.boundsMin() == std::array<float, 3>{1, 1, 5});
  CHECK(m.boundsMax() == std::array<float, 3>{3, 4, 5});
  int up = 0, down = 0;
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const Eigen::Vector3d n = vec(m.normals, v);
    up += n == Eigen::Vector3d(0, 0, 1);
    down += n == Eigen::Vector3d(0, 0, -1);
  }
  CHECK(up == 4);
  CHECK(down == 4);
  checkFlatNormals(m);
}

TEST_CASE("instances after one that lost triangles close up behind it", "[assemble]") {
  // Each instance is written where it would be if nothing were dropped, then moved back:
  // the cube after the flattened one must land right after its 8 surviving vertices.
  Scene s;
  s.add("cube", scaleTranslate({1, 1, 1}, {0, 0, 0}), {1, 0, 0});
  s.add("cube", scaleTranslate({2, 3, 0}, {1, 1, 5}), {0, 1, 0});
  s.add("cube", scaleTranslate({1, 2, 3}, {4, 0, 0}), {0, 0, 1});
  const Mesh m = s.assemble();
  Scene alone;
  alone.add("cube", scaleTranslate({1, 2, 3}, {4, 0, 0}), {0, 0, 1});
  const Mesh last = alone.assemble();
  REQUIRE(m.vertexCount() == 24 + 8 + 24);
  REQUIRE(m.triangleCount() == 12 + 4 + 12);
  for (size_t v = 0; v < 24; ++v) {
    CHECK(vec(m.positions, 32 + v) == vec(last.positions, v));
    CHECK(vec(m.normals, 32 + v) == vec(last.normals, v));
    CHECK(vec(m.colors, 32 + v) == Eigen::Vector3d(0, 0, 1));
  }
  for (size_t k = 0; k < 3 * 12; ++k) CHECK(m.indices[3 * 16 + k] == last.indices[k] + 32);
  for (size_t v = 24; v < 32; ++v) CHECK(vec(m.colors, v) == Eigen::Vector3d(0, 1, 0));
  for (uint32_t i : m.indices) CHECK(i < m.vertexCount());
  CHECK(signedVolume(m) == Approx(1 + 6));
  checkFlatNormals(m);
}

TEST_CASE("CGA's uv sets 1 to 9 move with their vertices and are 0 0 where an instance lacks them",
          "[assemble]") {
  // A library cube without sets, then the cube as own geometries carrying set 3 (u = the
  // vertex's number, v = 100 + it): flattened (only top and bottom survive, renumbered),
  // then whole with set 5 too. The sets come out ascending, each per output vertex.
  Scene s;
  s.add("cube", scaleTranslate({1, 1, 1}, {0, 0, 0}));
  std::string error;
  REQUIRE(resolveAssets(s.list, s.library, s.meshOf, error));
  Mesh own = s.library.mesh(s.meshOf[0]);
  const size_t n = own.vertexCount();
  own.uvSets.push_back({3, {}});
  for (size_t v = 0; v < n; ++v) own.uvSets[0].coords.insert(own.uvSets[0].coords.end(), {float(v), 100.0f + v});
  Mesh both = own;
  both.uvSets.push_back({5, {}});
  for (size_t v = 0; v < n; ++v) both.uvSets[1].coords.insert(both.uvSets[1].coords.end(), {-1.0f, -2.0f});
  for (const Mesh* g : {&own, &both}) {
    s.list.geometries.push_back(*g);
    s.add(kOwnGeometryAsset, g == &own ? scaleTranslate({2, 3, 0}, {1, 1, 5}) : scaleTranslate({1, 1, 1}, {4, 0, 0}));
    s.list.instances.back().geometry = uint32_t(s.list.geometries.size() - 1);
  }
  const Mesh m = s.assemble();
  REQUIRE(m.vertexCount() == n + 8 + n);
  REQUIRE(m.uvSets.size() == 2);
  CHECK(m.uvSets[0].set == 3);
  CHECK(m.uvSets[1].set == 5);
  const auto uv = [&](size_t k, size_t v) { return std::array<float, 2>{m.uvSets[k].coords[2 * v], m.uvSets[k].coords[2 * v + 1]}; };
  for (size_t v = 0; v < n; ++v) {  // the library cube: no sets
    CHECK(uv(0, v) == std::array<float, 2>{0, 0});
    CHECK(uv(1, v) == std::array<float, 2>{0, 0});
  }
  for (size_t v = n; v < n + 8; ++v) {  // the flattened one: each survivor keeps its own set 3
    const std::array<float, 2> c = uv(0, v);
    REQUIRE(c[0] >= 0);
    REQUIRE(size_t(c[0]) < n);
    CHECK(c[1] == 100.0f + c[0]);
    const Eigen::Vector3d unit = vec(own.positions, size_t(c[0]));
    CHECK(vec(m.positions, v) == Eigen::Vector3d(1 + 2 * unit.x(), 1 + 3 * unit.y(), 5));
    CHECK(uv(1, v) == std::array<float, 2>{0, 0});
  }
  for (size_t v = 0; v < n; ++v) {  // the whole one: both sets as given
    CHECK(uv(0, n + 8 + v) == std::array<float, 2>{float(v), 100.0f + v});
    CHECK(uv(1, n + 8 + v) == std::array<float, 2>{-1, -2});
  }
}

TEST_CASE("a quad scaled flat in X vanishes entirely", "[assemble]") {
  Scene s;
  s.add("quad", scaleTranslate({0, 1, 1}, {0, 0, 0}));
  s.add("quad", scaleTranslate({1, 1, 0}, {0, 0, 0}));  // z scale is irrelevant to a quad
  const Mesh m = s.assemble();
  CHECK(m.triangleCount() == 2);
  for (size_t v = 0; v < m.vertexCount(); ++v) CHECK(vec(m.normals, v) == Eigen::Vector3d(0, 0, 1));
}

TEST_CASE("mirrors, rotations and shears keep normals outward and consistent", "[assemble]") {
  Eigen::Matrix4d mirror = Eigen::Matrix4d::Identity();
  mirror(0, 0) = -1;
  Eigen::Matrix4d affine = Eigen::Matrix4d::Identity();
  affine.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
                             (Eigen::Matrix3d() << 2, 0.5, 0, 0, 1, 0.3, 0, 0, 3).finished();
  affine.block<3, 1>(0, 3) = Eigen::Vector3d(10, -4, 2);
  for (const auto& [name, t] : {std::pair{"mirror", mirror}, std::pair{"affine", affine}}) {
    INFO(name);
    Scene s;
    s.add("cube", toArray(t));
    const Mesh m = s.assemble();
    CHECK(m.triangleCount() == 12);
    CHECK(signedVolume(m) == Approx(std::abs(t.block<3, 3>(0, 0).determinant())));
    checkFlatNormals(m);
  }
}

TEST_CASE("smooth normals follow the inverse transpose of the transform", "[assemble]") {
  Scene s;
  s.add("sphere", scaleTranslate({4, 1, 1}, {0, 0, 0}));
  const Mesh m = s.assemble();
  Mesh unit;
  makeBuiltinPrimitive("sphere", unit);
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const Eigen::Vector3d expected = vec(unit.normals, v).cwiseQuotient(Eigen::Vector3d(4, 1, 1)).normalized();
    CHECK(vec(m.normals, v).dot(expected) == Approx(1.0).epsilon(1e-6));
  }
}

TEST_CASE("assembly bytes do not depend on the number of threads", "[assemble]") {
  Scene s;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const char* assets[] = {"torus", "cube", "sphere", "quad"};
  for (int i = 0; i < 3000; ++i) {
    Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) t(r, c) = 10 * u(rng);
    if (i % 7 == 0) t.col(2).head<3>().setZero();  // some flattened instances
    s.add(assets[i % 4], toArray(t), {float(u(rng) * 0.5 + 0.5), 0.5f, 0.25f});
  }
  const Mesh parallel = s.assemble();
  Mesh serial;
  tbb::task_arena(1).execute([&] { serial = assembleInstances(s.list, s.library, s.meshOf); });
  CHECK(parallel.positions == serial.positions);
  CHECK(parallel.normals == serial.normals);
  CHECK(parallel.colors == serial.colors);
  CHECK(parallel.indices == serial.indices);
  CHECK(countTriangles(s.list, s.library, s.meshOf) == parallel.triangleCount());
}

TEST_CASE("assembling into a reused mesh gives a fresh assembly's arrays", "[assemble]") {
  Scene s;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const char* assets[] = {"sphere", "cube", "bark", "quad"};
  for (int i = 0; i < 400; ++i) {
    Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) t(r, c) = 5 * u(rng);
    if (i % 5 == 0) t.col(1).head<3>().setZero();  // some flattened instances
    s.add(assets[i % 4], toArray(t), {0.5f, float(u(rng) * 0.5 + 0.5), 0.25f});
  }
  const Mesh fresh = s.assemble();
  REQUIRE(fresh.hasTexcoords());  // bark has texture coordinates, the cube does not
  // A mesh holding more than the assembly will, in every array, and one with none.
  Mesh larger;
  for (int i = 0; i < 3; ++i) assembleInstances(s.list, s.library, s.meshOf, larger);  // warm, and warm again
  larger.positions.insert(larger.positions.end(), 999, 7.0f);
  larger.normals.insert(larger.normals.end(), 999, 7.0f);
  larger.colors.insert(larger.colors.end(), 999, 7.0f);
  larger.texcoords.insert(larger.texcoords.end(), 999, 7.0f);
  larger.indices.insert(larger.indices.end(), 999, 7u);
  Scene rigidOnly;  // no texture coordinates at all: a reused mesh's must go
  rigidOnly.add("cube", scaleTranslate({1, 2, 3}, {0, 0, 0}));
  Mesh withoutTexcoords = larger;
  rigidOnly.assemble();
  assembleInstances(rigidOnly.list, rigidOnly.library, rigidOnly.meshOf, withoutTexcoords);
  CHECK(withoutTexcoords.texcoords.empty());
  CHECK(withoutTexcoords.positions == rigidOnly.assemble().positions);
  for (Mesh* reused : {&larger, &withoutTexcoords}) {
    const float* memory = reused->positions.data();
    assembleInstances(s.list, s.library, s.meshOf, *reused);
    if (reused == &larger) CHECK(reused->positions.data() == memory);  // room enough: no new memory
    CHECK(reused->positions == fresh.positions);
    CHECK(reused->normals == fresh.normals);
    CHECK(reused->colors == fresh.colors);
    CHECK(reused->texcoords == fresh.texcoords);
    CHECK(reused->indices == fresh.indices);
  }
}

// The scene's baked parts (runtime/output/scene.cpp) assemble a group's instances in
// place: the same arrays as the list of only those instances that it used to copy them
// into (their own geometries renumbered), small selections (run on the calling thread)
// and large ones alike.
TEST_CASE("a selection assembles as a list of only its instances", "[assemble]") {
  Scene s;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const char* assets[] = {"torus", "cube", "bark", "quad"};
  Mesh own;  // a triangle of its own geometry, in its unit box
  own.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  own.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  own.indices = {0, 1, 2};
  for (int i = 0; i < 600; ++i) {
    Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) t(r, c) = 4 * u(rng);
    if (i % 9 == 0) t.col(0).head<3>().setZero();  // some flattened instances
    s.add(i % 5 == 4 ? kOwnGeometryAsset : assets[i % 4], toArray(t), {0.25f, float(u(rng) * 0.5 + 0.5), 0.5f});
    if (i % 5 == 4) {
      own.positions[3] = float(1 + i % 3);  // geometries differ
      s.list.geometries.push_back(own);
      s.list.instances.back().geometry = uint32_t(s.list.geometries.size() - 1);
    }
  }
  std::string error;
  REQUIRE(resolveAssets(s.list, s.library, s.meshOf, error));
  std::vector<std::vector<uint32_t>> selections = {{4, 2, 9, 14}, {599}, {}};
  selections.emplace_back();
  for (uint32_t i = 1; i < 600; i += 2) selections.back().push_back(i);  // thousands of triangles: in parallel
  for (const std::vector<uint32_t>& which : selections) {
    InstanceList sub;  // what the scene built before: a list of copies
    sub.assets = s.list.assets;
    for (uint32_t i : which) {
      Instance inst = s.list.instances[i];
      if (inst.geometry != UINT32_MAX) {
        sub.geometries.push_back(s.list.geometries[inst.geometry]);
        inst.geometry = uint32_t(sub.geometries.size() - 1);
      }
      sub.instances.push_back(inst);
    }
    const Mesh expected = assembleInstances(sub, s.library, s.meshOf);
    Mesh selected;
    selected.positions.assign(5, 1.0f);  // replaced, as assembleInstances replaces
    assembleSelected(s.list, which, s.library, s.meshOf, selected);
    CHECK(selected.positions == expected.positions);
    CHECK(selected.normals == expected.normals);
    CHECK(selected.colors == expected.colors);
    CHECK(selected.texcoords == expected.texcoords);
    CHECK(selected.indices == expected.indices);
    CHECK(selected.triangleCount() == expected.triangleCount());
  }
  CHECK(assembleInstances(s.list, s.library, s.meshOf).triangleCount() > 0);
  Mesh out;
  CHECK_THROWS_AS(assembleSelected(s.list, {3, 600}, s.library, s.meshOf, out), std::out_of_range);
}

TEST_CASE("an unknown asset fails resolution with the library's message", "[assemble]") {
  Scene s;
  s.add("no_such_asset.obj", scaleTranslate({1, 1, 1}, {0, 0, 0}));
  std::string error;
  CHECK_FALSE(resolveAssets(s.list, s.library, s.meshOf, error));
  CHECK_THAT(error, Catch::Contains("no_such_asset.obj"));
}

namespace {
// A clock that stands still where the test puts it: the time left is what it says.
Deadline::Clock::time_point budgetClockNow;
Deadline::Clock::time_point readBudgetClock() { return budgetClockNow; }
}  // namespace

TEST_CASE("a scene-only run keeps the instances the assembly would keep in time", "[assemble]") {
  // 20 000 unit cubes (12 triangles, no line segments). A block takes instances while
  // its work (1 + 12 a cube) is under 32 768: 13 x 2 520 = 32 760, so 2 521 cubes, 30 252
  // triangles. With 1 s left and 1e-5 s a triangle, a block starts while 1e-5 x the
  // triangles before it is under 1 s: before blocks 0..3 (0, 30 252, 60 504, 90 756
  // triangles), not before block 4 (121 008): 4 x 2 521 = 10 084 cubes kept.
  Scene s;
  for (int i = 0; i < 20000; ++i) s.add("cube", scaleTranslate({1, 1, 1}, {2.0 * i, 0, 0}));
  std::string error;
  REQUIRE(resolveAssets(s.list, s.library, s.meshOf, error));
  const Deadline::Clock::time_point start{};
  budgetClockNow = start + std::chrono::seconds(1);
  const Deadline deadline(start, 2.0, &readBudgetClock);
  CHECK(output::instancesWithinTime(s.list, s.library, s.meshOf, deadline, 1e-5) == 10084);
  // The flattened assembly under the same clock keeps the same cubes.
  size_t assembled = 0;
  const Mesh mesh = assembleInstances(s.list, s.library, s.meshOf, &deadline, &assembled, 1e-5);
  CHECK(assembled == 10084);
  CHECK(mesh.triangleCount() == 12 * 10084);
  // No rate: only the deadline, not passed, so all; passed: none; no limit: all.
  CHECK(output::instancesWithinTime(s.list, s.library, s.meshOf, deadline, 0) == 20000);
  budgetClockNow = start + std::chrono::seconds(2);
  CHECK(output::instancesWithinTime(s.list, s.library, s.meshOf, deadline, 1e-5) == 0);
  CHECK(output::instancesWithinTime(s.list, s.library, s.meshOf, Deadline(), 1e-5) == 20000);
}
