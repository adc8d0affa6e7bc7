// Seeds whose plants cannot meet are derived apart, concurrently, and put together in
// seed order (backend/engine/seed_plants.cpp): the same output whatever the number of
// threads, --max-shapes counted over all plants, errors and limits as if the seeds were
// derived one after another.
#include "derive_helpers.h"

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include <cmath>

using namespace fgsg;
using fgsg::test::deriveText;
using fgsg::test::unitPoint;

namespace {

// A plant per seed on the unit sphere: random turns (each plant's own stream), a branch,
// smooth terminals on every segment.
const char* kPlants = R"(
  surface sphere(1);
  start = Walk(0)
  Walk(n) : n < 5 ~> Marching(0.1, Rand(-40, 40), true){ Leaf Stem } Branch(n == 2 ? 2 : 1){ Walk(n + 1), Walk(n + 1) }
  Leaf ~> I("cube")
  Stem ~> S(1, 0.02, 0.02) I("bark")
)";

rt::DeriveOptions withSeeds(int count) {
  rt::DeriveOptions o;
  for (int k = 0; k < count; ++k) {
    rt::DeriveOptions::Seed s;
    const double a = 2 * 3.14159265358979 * k / count;
    s.point[0] = std::cos(a), s.point[1] = std::sin(a), s.point[2] = 0.3;
    o.seeds.push_back(s);
  }
  return o;
}

rt::DeriveResult onThreads(int threads, const char* grammar, const rt::DeriveOptions& o) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return deriveText(grammar, o);
}

void requireSame(const rt::DeriveResult& a, const rt::DeriveResult& b) {
  REQUIRE(a.instances.instances.size() == b.instances.instances.size());
  for (size_t i = 0; i < a.instances.instances.size(); ++i) {
    const rt::Instance &x = a.instances.instances[i], &y = b.instances.instances[i];
    CHECK(x.transform == y.transform);
    CHECK(x.asset == y.asset);
    CHECK(x.curve == y.curve);
  }
  REQUIRE(a.instances.curves.size() == b.instances.curves.size());
  for (size_t c = 0; c < a.instances.curves.size(); ++c) CHECK(a.instances.curves[c].control == b.instances.curves[c].control);
  CHECK(a.instances.params == b.instances.params);
}

// Which seed an instance's plant grew from: the closest seed point.
size_t seedOf(const rt::Instance& inst, const rt::DeriveOptions& o) {
  const Eigen::Vector3d p = unitPoint(inst, 0, 0, 0);
  size_t best = 0;
  double nearest = 1e30;
  for (size_t k = 0; k < o.seeds.size(); ++k) {
    const double d = (p - Eigen::Vector3d(o.seeds[k].point[0], o.seeds[k].point[1], o.seeds[k].point[2])).norm();
    if (d < nearest) nearest = d, best = k;
  }
  return best;
}

}  // namespace

TEST_CASE("Independent seeds give the same output on one thread and on many, plant after plant", "[seeds]") {
  const rt::DeriveOptions o = withSeeds(6);
  const rt::DeriveResult one = onThreads(1, kPlants, o), many = onThreads(4, kPlants, o);
  REQUIRE(one.ok);
  REQUIRE(many.ok);
  requireSame(one, many);
  // 6 plants of 7 segments (steps 0-2, then two branches of steps 3-4: 3 + 2 x 2),
  // a leaf and a stem on each, then the surface.
  REQUIRE(one.instances.instances.size() == 6 * 7 * 2 + 1);
  CHECK(one.stats.instances == one.instances.instances.size());
  CHECK(one.instances.curves.size() == 6 * 7);
  // Plant after plant, in seed order; every stem follows a curve of its own plant.
  size_t previous = 0;
  for (size_t i = 0; i + 1 < one.instances.instances.size(); ++i) {
    const rt::Instance& inst = one.instances.instances[i];
    const size_t seed = seedOf(inst, o);
    CHECK(seed >= previous);
    previous = seed;
    if (inst.curve != UINT32_MAX) CHECK(inst.curve / 7 == seed);
  }
}

TEST_CASE("A seed's plant is the same with or without the seeds after it", "[seeds]") {
  rt::DeriveOptions two = withSeeds(6);
  two.seeds.resize(2);
  const rt::DeriveResult all = deriveText(kPlants, withSeeds(6)), first = deriveText(kPlants, two);
  REQUIRE(all.ok);
  REQUIRE(first.ok);
  const size_t n = first.instances.instances.size() - 1;  // without the surface
  REQUIRE(n == 2 * 7 * 2);
  for (size_t i = 0; i < n; ++i) CHECK(first.instances.instances[i].transform == all.instances.instances[i].transform);
}

TEST_CASE("The shape limit counts the shapes of every plant, in seed order", "[seeds][limits]") {
  rt::DeriveOptions o = withSeeds(6);
  const rt::DeriveResult whole = deriveText(kPlants, o);
  REQUIRE(whole.ok);
  const uint64_t perPlant = whole.stats.shapesCreated / 6;
  REQUIRE(whole.stats.shapesCreated == 6 * perPlant);
  // Room for two and a half plants: the first two whole, the third cut where a
  // derivation of the seeds one after another would stop, the rest not grown.
  o.maxShapes = 2 * perPlant + perPlant / 2;
  const rt::DeriveResult one = onThreads(1, kPlants, o), many = onThreads(4, kPlants, o);
  REQUIRE(one.ok);
  requireSame(one, many);
  CHECK(one.stats.shapesCreated == o.maxShapes);
  bool warned = false;
  for (const auto& m : one.messages) warned |= m.code == "R004" && m.message.find("--max-shapes") != std::string::npos;
  CHECK(warned);
  // What is kept is where the whole output begins (its plants come in the same order).
  const size_t kept = one.instances.instances.size() - 1;
  CHECK(kept > 2 * 7 * 2);
  CHECK(kept < 3 * 7 * 2);
  for (size_t i = 0; i < kept; ++i) CHECK(one.instances.instances[i].transform == whole.instances.instances[i].transform);
}

TEST_CASE("The first seed whose plant fails fails the derivation, whatever the threads", "[seeds][errors]") {
  // Seed 3's plant divides by zero (its start is the only one with x < -0.9).
  const char* grammar = R"(
    surface sphere(1);
    start = Walk(0)
    Walk(n) : n < 3 ~> Marching(0.1, 0, true){ I("cube") Walk(n + 1) }
    Walk(n) : n == 3 && Scope.px < -0.8 ~> S(1 / (n - 3), 1, 1) I("cube")
  )";
  const rt::DeriveOptions o = withSeeds(6);
  const rt::DeriveResult one = onThreads(1, grammar, o), many = onThreads(4, grammar, o);
  CHECK_FALSE(one.ok);
  CHECK_FALSE(many.ok);
  REQUIRE(one.messages.size() == 1);
  REQUIRE(many.messages.size() == 1);
  CHECK(one.messages[0].code == "R005");
  CHECK(one.messages[0].message == many.messages[0].message);
  CHECK(one.messages[0].line == many.messages[0].line);
}

TEST_CASE("Seeds whose plants can meet grow in one queue, as before", "[seeds]") {
  // IC tests every instance against all plants' earlier ones: derived together.
  const char* grammar = R"(
    surface sphere(1);
    start = Walk(0)
    Walk(n) : n < 4 ~> Marching(0.1, 0, true){ IC("cube") Walk(n + 1) }
  )";
  const rt::DeriveOptions o = withSeeds(3);
  const rt::DeriveResult r = onThreads(4, grammar, o);
  REQUIRE(r.ok);
  // Breadth-first in one queue: the plants' first steps come before any second step.
  REQUIRE(r.instances.instances.size() >= 4);
  std::vector<size_t> firstThree;
  for (size_t i = 0; i < 3; ++i) firstThree.push_back(seedOf(r.instances.instances[i], o));
  std::sort(firstThree.begin(), firstThree.end());
  CHECK(firstThree == std::vector<size_t>{0, 1, 2});
}
