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

// How the terminals on a march step join those of the steps next to it (the Marching
// rule's smoothness parameter, Buron et al. 2015, §6: "discontinuous, C0, C1"):
//  * C1: bent along a curve whose tangent at each node is shared with the other C1
//    segments there (runtime/marching/smooth_curves.h) — no crack, no kink;
//  * C0: bent along a curve of its own, tangent at each end to the surface along its own
//    chord — the curves meet at the nodes, and kink where the march turns;
//  * Discontinuous: not bent; the terminals stay rigid boxes along the straight chord.
enum class TerminalSmoothness : uint8_t { C1 = 0, C0 = 1, Discontinuous = 2 };

// One march step, from node `from` to node `to` (indices into the node list): its
// direction is the direction of growth.
struct MarchSegment {
  uint32_t from = 0, to = 0;
  TerminalSmoothness smoothness = TerminalSmoothness::C1;
};

}  // namespace fgsg::rt::marching
