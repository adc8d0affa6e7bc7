// Whether any two triangles of a flat layout overlap: texture coordinates that use the
// same place twice (mirrored halves sharing one texture, stacked islands).
// Triangles are binned into a uniform grid about the size of a triangle, so a sound layout
// is checked in time proportional to its size rather than to its square.
#pragma once

#include "runtime/atlas/atlas.h"

#include <array>
#include <vector>

namespace fgsg::rt::atlas {

struct UVOverlap {
  int first = -1, second = -1;  // triangle indices, first < second; -1: no overlap
  Vec2 where = Vec2::Zero();    // a point inside both
  bool found() const { return first >= 0; }
};

// The first overlapping pair in a deterministic scan. Triangles that only touch (a shared
// edge or corner, or an edge lying along another) do not overlap: interiors must
// intersect by more than `tolerance` (in the triangles' units) across every separating
// direction. Triangles must not be degenerate and their coordinates must stay within
// about 1e150 (so the layout's extent is finite); either orientation is accepted.
UVOverlap findUVOverlap(const std::vector<std::array<Vec2, 3>>& triangles, double tolerance);

}  // namespace fgsg::rt::atlas
