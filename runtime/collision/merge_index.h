// Merge-instancing (FGSG §4.4, IM): a new instance close enough in position and rotation
// to an earlier identical one (same asset) is not placed; instead the earlier one moves
// towards it "as if attracted": it becomes the mean of every instance merged into it
// (positions and sizes averaged, rotations interpolated), so merging is order-fair.
#pragma once

#include "runtime/point_grid.h"
#include "runtime/scope.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace fgsg::rt {

class MergeIndex {
 public:
  struct Merge {
    size_t target;     // the earlier instance (the id given to add())
    Mat4 transform;    // its new unit-box-to-world transform
    uint32_t slot = 0; // where the index keeps it
  };

  // How far a candidate (by its slot, the order of add()) is, given its straight centre
  // distance; for distances along a surface, which are never shorter.
  using Distance = std::function<double(uint32_t slot, double straight)>;

  // The earlier instance of `asset` nearest to `transform` (centre distance at most
  // maxDist — measured by `distance` when given —, rotation angle at most
  // maxAngleDegrees); false when there is none. Ties go to the earlier instance.
  bool find(uint32_t asset, const Mat4& transform, double maxDist, double maxAngleDegrees,
            Merge& out, const Distance& distance = nullptr);
  size_t size() const { return entries_.size(); }  // instances added (rollback removes some)
  // Records a placed instance (id: its index in the output).
  void add(uint32_t asset, size_t id, const Mat4& transform);
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
    size_t id;       // the instance
    Mat4 transform;  // current (after merges)
    uint32_t count;  // instances it stands for
  };
  struct LogItem {
    bool added;      // an add (else a merge)
    uint32_t slot;
    Mat4 before;     // merge: the transform before
  };

  std::vector<Entry> entries_;  // by slot: the order of add()
  PointGrid centres_;           // the entries' centres, ids = slots
  std::vector<uint32_t> nearby_;
  std::vector<LogItem> log_;
};

}  // namespace fgsg::rt
