// Instances placed when collisions matter (FGSG §4.4): every instance placed so far is
// an obstacle; IC asks whether a new one fits, IM merges it into an earlier twin, and a
// Lock set is placed all or nothing (a transaction the derivation can roll back).
#pragma once

#include "ir/ir.h"
#include "runtime/assets.h"
#include "runtime/collision/collision_world.h"
#include "runtime/collision/merge_index.h"
#include "runtime/derivation.h"
#include "runtime/instances.h"
#include "runtime/lines/line_network.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fgsg::backend {

class CollisionPlacement {
 public:
  CollisionPlacement(rt::AssetLibrary& assets, rt::InstanceList& out,
                     const ir::CollisionSettings& settings);

  // Geodesic centre distance (`collision geodesic R;` on a surface): the distance along
  // the surface between two scopes' surface points, or a value >= `limit` when it is
  // at least that.
  using SurfaceDistance = std::function<double(const rt::Scope& a, const rt::Scope& b, double limit)>;
  // Set before anything is placed.
  void measureAlongSurface(SurfaceDistance distance) { alongSurface_ = std::move(distance); }

  // Whether an instance of `asset` (an index into the output's assets) mapped by
  // `transform`, placed from `scope`, is free of every obstacle.
  bool fits(uint32_t asset, const rt::Mat4& transform, const rt::Scope& scope);
  // Records the instance just appended to the output, placed from `scope`, as an obstacle.
  void placed(const rt::Scope& scope);

  // IM: merges into an earlier instance of the same asset within the thresholds (moving
  // it, in the output too) and returns true; false when the instance must be placed, after
  // which placedMergeable() records it. Along the surface (`collision geodesic`) maxDist
  // is measured from `scope` to the scope the earlier instance was first placed from.
  bool mergeInto(uint32_t asset, const rt::Mat4& transform, double maxDist, double maxAngle, const rt::Scope& scope);
  void placedMergeable(uint32_t asset, const rt::Mat4& transform, const rt::Scope& scope);

  // Lock: everything placed, merged or drawn as a line after begin() can be undone.
  struct Transaction {
    size_t instances = 0, params = 0, obstacles = 0, merges = 0, lines = 0;
  };
  Transaction begin(const rt::LineNetwork& lines) const;
  void rollback(const Transaction& t, rt::LineNetwork& lines);

  uint64_t narrowPhaseTests() const { return world_.narrowPhaseTests(); }

 private:
  int mesh(uint32_t asset);
  static void setTransform(rt::Instance& inst, const rt::Mat4& m);

  rt::AssetLibrary& assets_;
  rt::InstanceList& out_;
  rt::CollisionWorld world_;
  double radius_ = 0;
  SurfaceDistance alongSurface_;    // set: centre distances are measured along the surface
  std::vector<rt::Scope> placedFrom_;  // geodesic only: per obstacle, the scope it was placed from
  rt::MergeIndex merges_;
  std::vector<rt::Scope> mergeableFrom_;  // geodesic only: per IM instance, the scope it was placed from
  std::vector<int> meshOf_;  // output asset -> library mesh (-1: not yet resolved)
};

// Appends every line of `lines` (two points or more) to the output — as one smooth swept
// tube, registered in `assets` as generated geometry named "<line N>", or, for a line
// with an asset, one instance of it per segment bent along the line smoothed as
// marching's terminals are (its X along the line, its Z along `normalAt`) — and to the
// output's line graph (InstanceList::lines).
void appendLineTubes(const rt::LineNetwork& lines, rt::AssetLibrary& assets, rt::InstanceList& out,
                     const std::vector<std::array<float, 3>>& symbolColor,
                     const std::function<rt::Vec3(const rt::Vec3&)>& normalAt);

}  // namespace fgsg::backend
