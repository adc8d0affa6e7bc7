// How the marches of a derivation ended (Buron et al. §5, §8), counted so that a march
// that could never start is not silent (#46): when every Marching stopped at its first
// step, one warning (R030) at the first Marching says why — the condition failed at every
// destination tried (the seeds may all lie where a texture context says no), no point lay
// a step away (the surface's open edge came first), or the step is longer than the surface.
#pragma once

#include "ir/ir.h"
#include "runtime/derivation.h"

#include <cstdint>
#include <optional>

namespace fgsg::backend {

struct MarchTally {
  uint64_t marches = 0;            // Marching ops applied
  uint64_t steps = 0;              // of those, the ones that reached a destination
  uint64_t conditionFailed = 0;    // stopped: the condition failed wherever a step landed
  uint64_t atEdge = 0;             // stopped: no direction tried reached a point a step away
  uint64_t tooLong = 0;            // stopped: the step is longer than the surface's diagonal
  int candidates = 0;              // --march-candidates (directions beside straight ahead)
  ir::Loc first;                   // the first Marching applied
  bool hasFirst = false;

  void add(const MarchTally& other);
  // The R030 warning when marches were made and none of them moved; nothing otherwise.
  std::optional<rt::DeriveMessage> neverStarted() const;
};

}  // namespace fgsg::backend
