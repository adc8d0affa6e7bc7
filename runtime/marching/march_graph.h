// The graph on-mesh marching leaves behind (Buron et al. 2015, §6): the points marching
// reached, with the surface normal there, and the segments marched between them. A node
// where a march continues has one segment in and one out; a branch point has more.
#pragma once

#include "runtime/scope.h"

#include <cstdint>

namespace fgsg::rt::marching {

struct MarchNode {
  Vec3 position = Vec3::Zero();  // on the surface, world space
  Vec3 normal = Vec3::Zero();    // the surface's unit normal there
};

// One march step, from node `from` to node `to` (indices into the node list): its
// direction is the direction of growth.
struct MarchSegment {
  uint32_t from = 0, to = 0;
};

}  // namespace fgsg::rt::marching
