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

// Moves the connected parts of `mesh`, and the whole faces `faces` of part `facePart[f]`
// with them (the same parts: faces are found by their first corner).
void perturbParts(Mesh& mesh, std::vector<std::vector<std::array<double, 3>>>& faces, double amount, uint64_t seed);

}  // namespace fgsg::rt::synthesis::continuous
