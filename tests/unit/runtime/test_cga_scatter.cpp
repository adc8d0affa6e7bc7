// CityEngine's scatter (runtime/cga/scatter.h): the points' count, that each lies in its
// domain (checked here by inequalities written from the shapes' dimensions, not by the
// sampler's own geometry), the share each part of a surface or solid gets (within a
// binomial bound), the gaussian's moments, and that a stream gives the same points again.
#include "runtime/cga/cga.h"
#include "runtime/cga/scatter.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <vector>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

constexpr double kTol = 1e-9;

std::vector<Scope> scatterAll(const Scope& scope, const GeomRef& geom, const GeometryArena& arena,
                              const ScatterSpec& spec, uint64_t key, int n) {
  ScatterSampler sampler;
  std::string error;
  REQUIRE(sampler.prepare(scope, geom, arena, spec, error));
  RandomStream rng{key, 0};
  std::vector<Scope> out(n);
  for (Scope& s : out) {
    INFO(error);
    REQUIRE(sampler.next(rng, s, error));
  }
  return out;
}

// The L: a 20 x 9 wing and a 9 x 9 one above it (z 9..18), extruded 4 m.
Part extrudedL(GeometryArena& arena) {
  Part lot, solid;
  std::string error;
  REQUIRE(footprint(Scope{}, {{0, 0}, {20, 0}, {20, 9}, {9, 9}, {9, 18}, {0, 18}}, {}, arena, lot, error));
  REQUIRE(extrude(lot.scope, lot.geom, 4, arena, solid, error));
  return solid;
}

// The point in the parent scope's frame (metres along its axes from its origin).
Vec3 localOf(const Scope& parent, const Scope& point) { return parent.axes.transpose() * (point.P - parent.P); }

// |k - n p| within 4.5 standard deviations of the binomial (fails by chance with
// probability below 1e-5; the streams here are fixed, so a pass stays a pass).
bool binomialPlausible(int k, int n, double p) {
  return std::abs(k - n * p) <= 4.5 * std::sqrt(n * p * (1 - p));
}

}  // namespace

TEST_CASE("scatter(scope, n, uniform): n points of size zero inside a turned scope, its axes kept", "[scatter]") {
  Scope parent;
  parent.P = Vec3(3, -2, 7);
  parent.axes = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  parent.S = Vec3(10, 4, 6);
  GeometryArena arena;
  ScatterSpec spec;
  spec.domain = ScatterDomain::Scope;
  const std::vector<Scope> points = scatterAll(parent, GeomRef{}, arena, spec, 42, 2000);
  REQUIRE(points.size() == 2000);
  Vec3 sum = Vec3::Zero();
  for (const Scope& p : points) {
    const Vec3 l = localOf(parent, p);
    for (int k = 0; k < 3; ++k) {
      REQUIRE(l[k] >= -kTol);
      REQUIRE(l[k] <= parent.S[k] + kTol);
    }
    REQUIRE(p.S == Vec3::Zero());
    REQUIRE((p.axes - parent.axes).norm() == 0.0);
    sum += l;
  }
  // Uniform: the mean is the centre, within 4.5 standard errors (size / sqrt(12 n)).
  for (int k = 0; k < 3; ++k)
    CHECK(std::abs(sum[k] / 2000 - parent.S[k] / 2) <= 4.5 * parent.S[k] / std::sqrt(12.0 * 2000));
}

TEST_CASE("scatter: the same stream gives the same points and another stream other points", "[scatter]") {
  Scope parent;
  parent.S = Vec3(5, 5, 5);
  GeometryArena arena;
  ScatterSpec spec;
  spec.domain = ScatterDomain::Volume;
  const auto a = scatterAll(parent, GeomRef{}, arena, spec, 7, 50);
  const auto b = scatterAll(parent, GeomRef{}, arena, spec, 7, 50);
  const auto c = scatterAll(parent, GeomRef{}, arena, spec, 8, 50);
  int same = 0, differ = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    same += a[i].P == b[i].P;
    differ += a[i].P != c[i].P;
  }
  CHECK(same == 50);
  CHECK(differ == 50);
}

TEST_CASE("scatter(surface, n, uniform): area-weighted, 2/3 of the points on a face twice as large as the other", "[scatter]") {
  // Two faces of one open polyhedron in a 2 x 1 x 1 scope: the floor (y = 0, 2 m x 1 m) and
  // the wall x = 0 (1 m x 1 m).
  GeometryArena arena;
  const GeomRef geom = arena.addPolyhedron({{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}},
                                            {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}});
  Scope parent;
  parent.S = Vec3(2, 1, 1);
  ScatterSpec spec;
  ScatterSampler sampler;
  std::string error;
  REQUIRE(sampler.prepare(parent, geom, arena, spec, error));
  CHECK(sampler.domain() == ScatterDomain::Surface);
  const int n = 3000;
  const auto points = scatterAll(parent, geom, arena, spec, 2026, n);
  int floor = 0;
  for (const Scope& p : points) {
    const Vec3 w = p.P;
    const bool onFloor = std::abs(w.y()) <= kTol && w.x() >= -kTol && w.x() <= 2 + kTol && w.z() >= -kTol &&
                         w.z() <= 1 + kTol;
    const bool onWall = std::abs(w.x()) <= kTol && w.y() >= -kTol && w.y() <= 1 + kTol && w.z() >= -kTol &&
                        w.z() <= 1 + kTol;
    REQUIRE((onFloor || onWall));
    // y along the face's normal; on the floor x stays the parent's.
    if (onFloor && !onWall) {
      ++floor;
      CHECK(std::abs(std::abs(p.Y().y()) - 1) <= kTol);
      CHECK((p.X() - Vec3::UnitX()).norm() <= kTol);
    } else if (onWall) {
      CHECK(std::abs(std::abs(p.Y().x()) - 1) <= kTol);
    }
    CHECK(std::abs(p.axes.determinant() - 1) <= kTol);
  }
  INFO("points on the floor: " << floor << " of " << n);
  CHECK(binomialPlausible(floor, n, 2.0 / 3.0));
}

TEST_CASE("scatter(volume, n, uniform) inside an extruded L, shared by the volumes of its arms", "[scatter]") {
  GeometryArena arena;
  std::string error;
  const Part solid = extrudedL(arena);  // 20 x 9 and 9 x 9 (z 9..18), 4 m high
  ScatterSpec spec;
  spec.domain = ScatterDomain::Volume;
  ScatterSampler sampler;
  REQUIRE(sampler.prepare(solid.scope, solid.geom, arena, spec, error));
  CHECK(sampler.domain() == ScatterDomain::Volume);
  const int n = 2000;
  const auto points = scatterAll(solid.scope, solid.geom, arena, spec, 99, n);
  int upperArm = 0;
  for (const Scope& p : points) {
    const double x = p.P.x(), y = p.P.y(), z = p.P.z();
    REQUIRE(y >= -kTol);
    REQUIRE(y <= 4 + kTol);
    const bool wide = x >= -kTol && x <= 20 + kTol && z >= -kTol && z <= 9 + kTol;
    const bool arm = x >= -kTol && x <= 9 + kTol && z >= 9 - kTol && z <= 18 + kTol;
    REQUIRE((wide || arm));
    upperArm += z > 9;
  }
  INFO("points in the 9 x 9 arm: " << upperArm << " of " << n);
  CHECK(binomialPlausible(upperArm, n, 81.0 / 261.0));
}

TEST_CASE("scatter: a deadline that has passed stops the draws of one point", "[scatter]") {
  // The solid's draws each test every triangle: --max-seconds must reach inside them.
  GeometryArena arena;
  std::string error;
  const Part solid = extrudedL(arena);
  for (ScatterDomain domain : {ScatterDomain::Volume, ScatterDomain::Surface}) {
    ScatterSpec spec;
    spec.domain = domain;
    ScatterSampler sampler;
    REQUIRE(sampler.prepare(solid.scope, solid.geom, arena, spec, error));
    RandomStream rng{7, 0};
    Scope point;
    Deadline open = Deadline::after(3600);
    CHECK(sampler.next(rng, point, error, &open));
    Deadline passed(Deadline::Clock::now() - std::chrono::seconds(10), 1.0);
    CHECK_THROWS_AS(sampler.next(rng, point, error, &passed), TimeLimitReached);
  }
}

TEST_CASE("scatter(volume) on a shape that is no closed solid falls back to its surface", "[scatter]") {
  GeometryArena arena;
  Part lot;
  std::string error;
  REQUIRE(footprint(Scope{}, {{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}, arena, lot, error));
  ScatterSpec spec;
  spec.domain = ScatterDomain::Volume;
  ScatterSampler sampler;
  REQUIRE(sampler.prepare(lot.scope, lot.geom, arena, spec, error));
  CHECK(sampler.domain() == ScatterDomain::Surface);
  for (const Scope& p : scatterAll(lot.scope, lot.geom, arena, spec, 5, 200)) {
    CHECK(std::abs(p.P.y()) <= kTol);
    CHECK(p.P.x() >= -kTol);
    CHECK(p.P.x() <= 10 + kTol);
  }
  // A flat box (a footprint's scope) is no solid either; a line has no surface at all.
  Scope flatBox;
  flatBox.S = Vec3(4, 0, 4);
  REQUIRE(sampler.prepare(flatBox, GeomRef{}, arena, spec, error));
  CHECK(sampler.domain() == ScatterDomain::Surface);
  CHECK_FALSE(sampler.empty());
  Scope line;
  line.S = Vec3(4, 0, 0);
  REQUIRE(sampler.prepare(line, GeomRef{}, arena, spec, error));
  CHECK(sampler.empty());
}

TEST_CASE("scatter(scope, n, gaussian, left, relative 0.1): a half-normal from the left side, every point inside", "[scatter]") {
  Scope parent;
  parent.S = Vec3(10, 4, 6);
  GeometryArena arena;
  ScatterSpec spec;
  spec.domain = ScatterDomain::Scope;
  spec.gaussian = true;
  spec.mean = ScatterMean::Left;
  spec.stddev = 0.1;  // relative: 1 m along x, 0.4 m along y, 0.6 m along z
  const int n = 4000;
  Vec3 sum = Vec3::Zero();
  for (const Scope& p : scatterAll(parent, GeomRef{}, arena, spec, 11, n)) {
    for (int k = 0; k < 3; ++k) {
      REQUIRE(p.P[k] >= 0);
      REQUIRE(p.P[k] <= parent.S[k]);
    }
    sum += p.P;
  }
  // x: a normal cut at its mean, sigma sqrt(2 / pi) on average, spread sigma sqrt(1 - 2 / pi).
  const double sigma = 1.0;
  CHECK(std::abs(sum.x() / n - sigma * std::sqrt(2 / M_PI)) <= 4.5 * sigma * std::sqrt(1 - 2 / M_PI) / std::sqrt(n));
  CHECK(std::abs(sum.y() / n - 2) <= 4.5 * 0.4 / std::sqrt(n));
  CHECK(std::abs(sum.z() / n - 3) <= 4.5 * 0.6 / std::sqrt(n));
}

TEST_CASE("scatter(surface, n, gaussian, center, 1): a normal of 1 m about the centre of the lot", "[scatter]") {
  Scope lot;
  lot.S = Vec3(10, 0, 10);  // a flat box: its one face, y = 0
  GeometryArena arena;
  ScatterSpec spec;
  spec.gaussian = true;
  spec.stddev = 1;
  spec.relative = false;
  const int n = 4000;
  double sx = 0, sxx = 0;
  for (const Scope& p : scatterAll(lot, GeomRef{}, arena, spec, 3, n)) {
    REQUIRE(std::abs(p.P.y()) <= kTol);
    REQUIRE(p.P.x() >= 0);
    REQUIRE(p.P.x() <= 10);
    sx += p.P.x();
    sxx += p.P.x() * p.P.x();
  }
  const double mean = sx / n, variance = sxx / n - mean * mean;
  CHECK(std::abs(mean - 5) <= 4.5 / std::sqrt(n));
  CHECK(std::abs(variance - 1) <= 4.5 * std::sqrt(2.0 / n));
}

TEST_CASE("scatter: the deviation of a gaussian must be a positive number", "[scatter]") {
  Scope parent;
  GeometryArena arena;
  ScatterSpec spec;
  spec.gaussian = true;
  spec.stddev = 0;
  ScatterSampler sampler;
  std::string error;
  CHECK_FALSE(sampler.prepare(parent, GeomRef{}, arena, spec, error));
  CHECK(error.find("standard deviation") != std::string::npos);
}
