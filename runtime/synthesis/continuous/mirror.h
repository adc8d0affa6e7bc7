// Mirror symmetry of continuous synthesis (the symmetry constraint of §3.5.2 carried to
// planes): the output is its own mirror image across the middle of the box along x or z.
// A vertex's label must be the mirror image of its mirror vertex's label — a link with
// the map as its relation, as the discrete solver's symmetry links.
#pragma once

#include "runtime/synthesis/continuous/arrangement.h"
#include "runtime/synthesis/continuous/labels.h"

#include <string>
#include <vector>

namespace fgsg::rt::synthesis::continuous {

// Per label, the index of its mirror image across `axis` (0 x, 2 z) in `labels`, -1 when
// the example has no such figure. False with a message when a direction's mirror image
// is not among `dirs`.
bool mirrorLabels(const std::vector<IVec3>& dirs, const std::vector<Label>& labels, int axis, std::vector<int32_t>& out,
                  std::string& error);

// Per vertex, its mirror vertex across the middle of the box along `axis`; false with a
// message when the arrangement is not symmetric (a fixed width that does not divide
// the box evenly).
bool mirrorVertices(const Arrangement& A, int axis, std::vector<int32_t>& out, std::string& error);

}  // namespace fgsg::rt::synthesis::continuous
