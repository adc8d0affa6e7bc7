// Colour symmetry of an evolved pattern (Chan & Hui 2013 §6.4: "L-system can be used to
// control the color symmetry of the pattern").
//
// The paper gives the idea, not a rule; our reading: the L-system decides where colours
// change and the pattern's own symmetry decides which parts share one. Every cell of L-system
// generation `level` (a block of k^(generation - level) x k^(generation - level) cells of
// the final pattern, all descended from it) carries one colour. Two blocks share a colour
// when a symmetry of the pattern carries one onto the other:
//   * the quarter turn (cell (r, c) to (n-1-c, r), each allele gaining a turn) and the half
//     turn, checked block by block: block B joins its image when every cell of B, turned,
//     looks like (fitness.h) the cell it lands on. So the corner blocks of a p4 pattern
//     (§6.1, the four-fold centre) share colours, and so does any block that happens to be
//     turned alike;
//   * the mirrors III-VI of §4.1.3.1 when the whole pattern has them (PatternMeasure).
// The classes are the connected groups of these joins (union-find), numbered by their
// first block in row order, so the colouring is exactly as symmetric as the pattern is:
// a symmetry of the pattern carries every colour class onto one class, and a turn the
// pattern lacks is not imposed on the colours.
#pragma once

#include "runtime/evolve/fitness.h"
#include "runtime/evolve/lsystem2d.h"

#include <array>
#include <vector>

namespace fgsg::rt::evolve {

struct ColourClasses {
  int blockSide = 1;         // cells a block side
  int classCount = 0;        // classes 0 .. classCount - 1
  std::vector<int> ofCell;   // the class of every cell of the pattern, row-major
};

// `blockSide` must divide the pattern's side (std::invalid_argument otherwise).
ColourClasses colourClasses(const PatternMeasure& measure, const AlleleGrid& pattern, int blockSide);

// The colour of class `c`: a fixed palette of 8 distinct colours, repeated past 8.
std::array<float, 3> classColour(int c);

}  // namespace fgsg::rt::evolve
