// Occlusion queries (CGA's Scope.occ): is a scope box free of, partly inside, or fully
// inside the boxes of the instances placed so far? Boxes are oriented (OBB); the test
// is the exact separating-axis test, after a cheap bounding-box rejection.
#pragma once

#include "runtime/scope.h"

#include <algorithm>
#include <vector>

namespace fgsg::rt {

enum class Occlusion { None, Partial, Full };

class OcclusionIndex {
 public:
  void add(const Scope& box);
  // Undo for all-or-nothing placement (Lock): keeps the first `count` boxes.
  size_t size() const { return boxes_.size(); }
  void truncate(size_t count) { boxes_.resize(std::min(count, boxes_.size())); }
  // Touching faces do not count: the query box is shrunk by a small tolerance first.
  Occlusion test(const Scope& query) const;

 private:
  struct Box {
    Vec3 center, half;  // half extents along the axes
    Mat3 axes;
    Vec3 lo, hi;  // world bounds
  };
  static Box makeBox(const Scope& s, double shrink);
  static bool intersects(const Box& a, const Box& b);
  static bool contains(const Box& outer, const Box& inner);

  std::vector<Box> boxes_;
};

}  // namespace fgsg::rt
