// Merge-instancing (FGSG §4.4, IM): a new instance close enough in position and rotation
// to an earlier identical one (same asset) is not placed; instead the earlier one moves
// towards it "as if attracted": it becomes the mean of every instance merged into it
// (positions and sizes averaged, rotations interpolated), so merging is order-fair.
#pragma once

#include "runtime/scope.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace fgsg::rt {

class MergeIndex {
 public:
  struct Merge {
    size_t target;     // the earlier instance (the id given to add())
    Mat4 transform;    // its new unit-box-to-world transform
  };

  // The earlier instance of `asset` nearest to `transform` (centre distance at most
  // maxDist, rotation angle at most maxAngleDegrees); false when there is none. Ties go
  // to the earlier instance.
  bool find(uint32_t asset, const Mat4& transform, double maxDist, double maxAngleDegrees,
            Merge& out) const;
  // Records a placed instance (id: its index in the output); maxDist is its IM distance
  // (the first one sizes the search grid).
  void add(uint32_t asset, size_t id, const Mat4& transform, double maxDist);
  // Applies a merge found by find(): the target now stands for one more instance.
  void apply(const Merge& m);

  // All-or-nothing placement (Lock): everything after mark() is undone by rollback(),
  // which returns the merges it undid as (target, transform before) so the caller can
  // restore the instances it had moved.
  size_t mark() const { return log_.size(); }
  std::vector<std::pair<size_t, Mat4>> rollback(size_t mark);

 private:
  struct Entry {
    uint32_t asset;
    Mat4 transform;  // current (after merges)
    uint32_t count;  // instances it stands for
  };
  struct LogItem {
    bool added;      // an add (else a merge)
    size_t id;
    Mat4 before;     // merge: the transform before
  };
  // Centres are bucketed in a grid whose cell is fixed by the first instance's distance.
  void cellOf(const Vec3& p, int64_t* c) const;
  static uint64_t key(int64_t x, int64_t y, int64_t z);
  void unlinkFromCell(size_t id);
  void linkToCell(size_t id);

  std::unordered_map<size_t, Entry> entries_;
  std::unordered_map<uint64_t, std::vector<size_t>> grid_;
  std::unordered_map<size_t, std::array<int64_t, 3>> cellOfId_;
  double cell_ = 0;  // 0: not yet fixed
  std::vector<LogItem> log_;
};

// The centre of an instance's unit box in world space.
Vec3 instanceCentre(const Mat4& unitBoxToWorld);

}  // namespace fgsg::rt
