// Collision-tested instancing (FGSG §4.4): every instance placed so far is an obstacle,
// and a new instance asks whether it would intersect any of them. Exact tests compare
// the instances' triangle meshes (FCL: BVH against BVH under rigid transforms, a dynamic
// AABB tree as broad phase) and then whole-volume containment, which triangle tests miss;
// the cheap alternative compares instance centres against a radius; the clearance test
// asks whether the meshes come closer than a distance (FGSG §4.4's "minimal distance
// between two shapes using a distance field": each mesh's distance field, evaluated
// exactly on the other's surface by FCL's BVH distance query). The implementation
// is loaded when the first obstacle is added (collision_backend.h).
#pragma once

#include "runtime/assets.h"
#include "runtime/scope.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>

namespace fgsg::rt {

enum class CollisionTest : uint8_t {
  Mesh,    // the instances' meshes intersect, or one encloses the other
  Centre,    // the instances' centres (their unit boxes' centres) are closer than a radius
  Distance,  // the meshes are closer than a radius (a clearance), or one encloses the other
};

class CollisionBackend;

class CollisionWorld {
 public:
  // `assets` supplies the meshes (in the unit box) that instances refer to by index; it
  // must outlive the world. `radius` is used by CollisionTest::Centre and ::Distance.
  CollisionWorld(const AssetLibrary& assets, CollisionTest test, double radius);
  ~CollisionWorld();
  CollisionWorld(const CollisionWorld&) = delete;
  CollisionWorld& operator=(const CollisionWorld&) = delete;

  // Would an instance of asset `mesh` mapped by `unitBoxToWorld` collide with an
  // obstacle? Touching counts as colliding. Does not add it. With the centre test,
  // `confirm`, when given, has the last word on each obstacle whose centre lies within
  // the radius (a geodesic distance is never shorter than the Euclidean one, so those
  // are the only candidates).
  bool collides(int mesh, const Mat4& unitBoxToWorld,
                const std::function<bool(size_t obstacle)>& confirm = nullptr);
  // Adds an instance as an obstacle; returns its id (ids count up from 0).
  size_t add(int mesh, const Mat4& unitBoxToWorld);
  // Moves obstacle `id` (a merged IM instance attracted towards its twin).
  void move(size_t id, const Mat4& unitBoxToWorld);

  // All-or-nothing placement (Lock): obstacles added after mark() go with rollback().
  size_t mark() const;
  void rollback(size_t mark);

  size_t size() const;
  uint64_t narrowPhaseTests() const;  // pairs compared exactly (for benchmarks)

 private:
  CollisionBackend& backend();

  const AssetLibrary& assets_;
  CollisionTest test_;
  double radius_;
  std::unique_ptr<CollisionBackend> impl_;  // null until the first obstacle
};

}  // namespace fgsg::rt
