// §4.8's post-process: outputs on parallel planes stand in rows and columns; moving each
// part a little at random breaks the grid look. A part moves along x and z by up to
// `amount` (world units), never so far that its box would meet another part's box (it
// tries half the move, then a quarter, then stays).
#pragma once

#include "runtime/mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace fgsg::rt::synthesis::continuous {

// Moves the `parts` connected parts of `mesh` (vertex v in part vertexPart[v]) and the
// whole faces with them (face f in part facePart[f]).
void perturbParts(Mesh& mesh, const std::vector<uint32_t>& vertexPart, std::vector<std::vector<std::array<double, 3>>>& faces,
                  const std::vector<uint32_t>& facePart, uint32_t parts, double amount, uint64_t seed);

}  // namespace fgsg::rt::synthesis::continuous
