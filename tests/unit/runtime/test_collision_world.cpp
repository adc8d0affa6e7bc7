// Collision-tested instancing's obstacle world: exact mesh tests under rotation and
// scale, containment (which triangle tests alone miss), the centre-distance and
// clearance tests,
// moving obstacles and rolling back a transaction; and merge-instancing's thresholds.
#include "runtime/collision/collision_world.h"
#include "runtime/collision/merge_index.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;

namespace {

// The unit box scaled by `size`, turned by `degrees` about Z, with its centre at `centre`.
Mat4 box(Vec3 centre, Vec3 size, double degrees = 0) {
  const Mat3 R = Eigen::AngleAxisd(degrees * M_PI / 180, Vec3::UnitZ()).toRotationMatrix();
  Mat4 m = Mat4::Identity();
  m.block<3, 3>(0, 0) = R * size.asDiagonal();
  m.block<3, 1>(0, 3) = centre - R * (0.5 * size);
  return m;
}

struct Assets {
  AssetLibrary library;
  int cube, sphere, quad;
  Assets() {
    std::string error;
    cube = library.resolve("cube", error);
    sphere = library.resolve("sphere", error);
    quad = library.resolve("quad", error);
    REQUIRE((cube >= 0 && sphere >= 0 && quad >= 0));
  }
};

}  // namespace

TEST_CASE("overlapping boxes collide, separated ones do not", "[collision]") {
  Assets a;
  CollisionWorld world(a.library, CollisionTest::Mesh, 0);
  CHECK_FALSE(world.collides(a.cube, box({0, 0, 0}, {1, 1, 1})));  // nothing placed yet
  world.add(a.cube, box({0, 0, 0}, {1, 1, 1}));
  CHECK(world.collides(a.cube, box({0.9, 0, 0}, {1, 1, 1})));
  CHECK_FALSE(world.collides(a.cube, box({1.01, 0, 0}, {1, 1, 1})));
  // A 45-degree box reaches sqrt(2)/2 from its centre: at 1.2 it overlaps, at 1.25 not.
  CHECK(world.collides(a.cube, box({1.2, 0, 0}, {1, 1, 1}, 45)));
  CHECK_FALSE(world.collides(a.cube, box({1.22, 0, 0}, {1, 1, 1}, 45)));
  CHECK(world.size() == 1);
}

TEST_CASE("an instance wholly inside another collides", "[collision]") {
  Assets a;
  CollisionWorld world(a.library, CollisionTest::Mesh, 0);
  world.add(a.cube, box({0, 0, 0}, {4, 4, 4}));
  CHECK(world.collides(a.sphere, box({0.5, 0, 0}, {1, 1, 1})));  // no surfaces cross
  CollisionWorld inner(a.library, CollisionTest::Mesh, 0);
  inner.add(a.sphere, box({0, 0, 0}, {0.5, 0.5, 0.5}));
  CHECK(inner.collides(a.cube, box({0, 0, 0}, {3, 3, 3})));  // the new one encloses it
  // A quad is open: it encloses nothing, and a small box beside its plane fits.
  CollisionWorld flat(a.library, CollisionTest::Mesh, 0);
  flat.add(a.quad, box({0, 0, 0}, {4, 4, 0}));
  CHECK_FALSE(flat.collides(a.cube, box({0, 0, 0.6}, {1, 1, 1})));
  CHECK(flat.collides(a.cube, box({0, 0, 0.4}, {1, 1, 1})));
}

// docs/language.md: only a closed mesh encloses another. An open tube (no caps) with
// room inside leaves a small cube in its hollow alone; a capped cylinder of the same
// size holds it and so collides. Both tests that look for enclosure agree.
TEST_CASE("only a closed mesh encloses another", "[collision]") {
  Assets a;
  std::string error;
  const int tube = a.library.resolve("tube16", error);
  const int cylinder = a.library.resolve("cylinder", error);
  REQUIRE((tube >= 0 && cylinder >= 0));
  for (CollisionTest test : {CollisionTest::Mesh, CollisionTest::Distance}) {
    CAPTURE(static_cast<int>(test));
    // The inner cube keeps 1.5 from every wall, more than the clearance of 0.1.
    const Mat4 inner = box({0, 0, 0}, {0.5, 0.5, 0.5});
    CollisionWorld open(a.library, test, 0.1);
    open.add(tube, box({0, 0, 0}, {4, 4, 4}));
    CHECK_FALSE(open.collides(a.cube, inner));
    CHECK_FALSE(open.collides(a.cube, box({0.3, -0.4, 0.2}, {0.5, 0.5, 0.5}, 30)));
    // Around the other way: a tube placed over a cube already there does not enclose it.
    CollisionWorld openAround(a.library, test, 0.1);
    openAround.add(a.cube, inner);
    CHECK_FALSE(openAround.collides(tube, box({0, 0, 0}, {4, 4, 4})));
    CollisionWorld closed(a.library, test, 0.1);
    closed.add(cylinder, box({0, 0, 0}, {4, 4, 4}));
    CHECK(closed.collides(a.cube, inner));
    CHECK(closed.collides(a.cube, box({0.3, -0.4, 0.2}, {0.5, 0.5, 0.5}, 30)));
    CollisionWorld closedAround(a.library, test, 0.1);
    closedAround.add(a.cube, inner);
    CHECK(closedAround.collides(cylinder, box({0, 0, 0}, {4, 4, 4})));
    // The tube's wall itself still collides: open meshes are obstacles, only not solid.
    CHECK(open.collides(a.cube, box({1.9, 0, 0}, {0.5, 0.5, 0.5})));
  }
}

TEST_CASE("scaled instances share a mesh but keep their own sizes", "[collision]") {
  Assets a;
  CollisionWorld world(a.library, CollisionTest::Mesh, 0);
  for (int i = 0; i < 10; ++i) world.add(a.cube, box({3.0 * i, 0, 0}, {2, 0.5, 0.5}));
  // Box 4 spans x 11..13 and box 5 14..16.
  CHECK(world.collides(a.cube, box({13.4, 0, 0}, {1, 0.5, 0.5})));  // from 12.9
  CHECK_FALSE(world.collides(a.cube, box({13.5, 0, 0}, {0.8, 0.5, 0.5})));  // 13.1..13.9
  CHECK(world.collides(a.cube, box({13.5, 0, 0}, {1.2, 0.5, 0.5})));  // to 14.1
  CHECK(world.narrowPhaseTests() > 0);
}

TEST_CASE("centre distance collides below the radius only", "[collision]") {
  Assets a;
  CollisionWorld world(a.library, CollisionTest::Centre, 1.0);
  world.add(a.cube, box({0, 0, 0}, {0.1, 0.1, 0.1}));
  CHECK(world.collides(a.cube, box({0.99, 0, 0}, {0.1, 0.1, 0.1})));
  CHECK_FALSE(world.collides(a.cube, box({1.01, 0, 0}, {0.1, 0.1, 0.1})));
  // Exactly at the radius is not closer than it (the grid's lookup includes it; the
  // test itself must not: a mutation run found nothing asking, #51).
  CHECK_FALSE(world.collides(a.cube, box({1.0, 0, 0}, {0.1, 0.1, 0.1})));
  CHECK(world.collides(a.cube, box({-0.6, 0.6, 0.3}, {5, 5, 5})));  // sizes do not matter
}

TEST_CASE("the clearance test collides when the meshes come closer than the distance", "[collision]") {
  Assets a;
  CollisionWorld world(a.library, CollisionTest::Distance, 0.5);
  world.add(a.cube, box({0, 0, 0}, {1, 1, 1}));  // faces at x = +-0.5
  // Face to face: a gap of 0.45 is too close, 0.55 keeps the clearance.
  CHECK(world.collides(a.cube, box({1.45, 0, 0}, {1, 1, 1})));
  CHECK_FALSE(world.collides(a.cube, box({1.55, 0, 0}, {1, 1, 1})));
  // Corner to corner along the diagonal of the XY plane: the gap is the distance between
  // the corners (0.5, 0.5) and (c - 0.5, c - 0.5), sqrt(2) (c - 1).
  const double inside = 1 + 0.49 / std::sqrt(2.0), outside = 1 + 0.51 / std::sqrt(2.0);
  CHECK(world.collides(a.cube, box({inside, inside, 0}, {1, 1, 1})));
  CHECK_FALSE(world.collides(a.cube, box({outside, outside, 0}, {1, 1, 1})));
  // A sphere (a 32-segment polygon in section, so its surface reaches 0.5 only at its
  // vertices) beside the cube, scaled and turned: the gap is measured on the meshes.
  CHECK(world.collides(a.sphere, box({0, 1.4, 0}, {1, 1, 1}, 30)));
  CHECK_FALSE(world.collides(a.sphere, box({0, 1.6, 0}, {1, 1, 1}, 30)));
  CHECK(world.collides(a.sphere, box({0, 2.2, 0}, {2.5, 2.5, 2.5})));  // reaches 0.95
  // Touching, crossing and enclosing are all closer than any clearance.
  CHECK(world.collides(a.cube, box({1, 0, 0}, {1, 1, 1})));
  CHECK(world.collides(a.cube, box({0.3, 0, 0}, {1, 1, 1})));
  CHECK(world.collides(a.sphere, box({0, 0, 0}, {0.2, 0.2, 0.2})));
  CHECK(world.narrowPhaseTests() > 0);
}

TEST_CASE("moved obstacles are tested where they are now", "[collision]") {
  Assets a;
  for (CollisionTest test : {CollisionTest::Mesh, CollisionTest::Centre, CollisionTest::Distance}) {
    CollisionWorld world(a.library, test, 0.5);
    const size_t id = world.add(a.cube, box({0, 0, 0}, {0.4, 0.4, 0.4}));
    world.move(id, box({10, 0, 0}, {0.4, 0.4, 0.4}));
    CHECK_FALSE(world.collides(a.cube, box({0, 0, 0}, {0.4, 0.4, 0.4})));
    CHECK(world.collides(a.cube, box({10.1, 0, 0}, {0.4, 0.4, 0.4})));
  }
}

TEST_CASE("rollback removes the obstacles added after the mark", "[collision]") {
  Assets a;
  for (CollisionTest test : {CollisionTest::Mesh, CollisionTest::Centre, CollisionTest::Distance}) {
    CollisionWorld world(a.library, test, 0.5);
    world.add(a.cube, box({0, 0, 0}, {0.4, 0.4, 0.4}));
    const size_t mark = world.mark();
    world.add(a.cube, box({5, 0, 0}, {0.4, 0.4, 0.4}));
    world.add(a.cube, box({5, 0, 0.1}, {0.4, 0.4, 0.4}));
    CHECK(world.collides(a.cube, box({5, 0, 0}, {0.4, 0.4, 0.4})));
    world.rollback(mark);
    CHECK(world.size() == 1);
    CHECK_FALSE(world.collides(a.cube, box({5, 0, 0}, {0.4, 0.4, 0.4})));
    CHECK(world.collides(a.cube, box({0, 0, 0.1}, {0.4, 0.4, 0.4})));
  }
}

TEST_CASE("merging respects the distance and angle thresholds", "[collision][merge]") {
  MergeIndex index;
  index.add(0, 0, box({0, 0, 0}, {1, 1, 1}));
  MergeIndex::Merge m;
  CHECK_FALSE(index.find(0, box({0.51, 0, 0}, {1, 1, 1}), 0.5, 10, m));  // too far
  CHECK_FALSE(index.find(0, box({0.2, 0, 0}, {1, 1, 1}, 11), 0.5, 10, m));  // turned too much
  CHECK_FALSE(index.find(1, box({0.2, 0, 0}, {1, 1, 1}), 0.5, 10, m));  // another asset
  REQUIRE(index.find(0, box({0.4, 0, 0}, {1, 1, 1}, 8), 0.5, 10, m));
  CHECK(m.target == 0);
  // The merged instance moves half way: mean position, half the turn.
  CHECK(instanceCentre(m.transform).isApprox(Vec3(0.2, 0, 0), 1e-12));
  CHECK(m.transform.isApprox(box({0.2, 0, 0}, {1, 1, 1}, 4), 1e-12));
  index.apply(m);
  // It now stands for two: a third pulls it a third of the way.
  REQUIRE(index.find(0, box({0.5, 0, 0}, {1, 1, 1}, 4), 0.5, 10, m));
  CHECK(instanceCentre(m.transform).isApprox(Vec3(0.3, 0, 0), 1e-12));
  const auto undone = index.rollback(1);
  REQUIRE(undone.size() == 1);
  CHECK(undone[0].second.isApprox(box({0, 0, 0}, {1, 1, 1}), 1e-12));
  REQUIRE(index.find(0, box({0.5, 0, 0}, {1, 1, 1}), 0.5, 10, m));
  CHECK(instanceCentre(m.transform).isApprox(Vec3(0.25, 0, 0), 1e-12));
}
