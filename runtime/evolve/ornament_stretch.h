// How much the inverse poly-cube map (polycube_map.h) stretches the pattern's cells (Chan &
// Hui 2013 §6.4: on thin parts, a bunny's ears or an elephant's trunk, the ornament runs
// into long streaks). A pattern of n x n cells on a face-let puts cell (row, column) on
// the face-let square [column/n, (column+1)/n] x [(n-1-row)/n, (n-row)/n] (row 0 at the
// top, as surface_ornament.h lays it); its four corners are carried onto the surface and
// the cell's stretch is
//   longest / shortest of the four mapped sides (chords between mapped corners),
// 1 for a cell mapped by a similarity, larger the longer and thinner its image is. A side
// collapsed to a point gives infinity. Chords, not arcs: a side folded over a sharp edge
// counts by its ends (a cell is small against the surface's features at any useful n).
#pragma once

#include "runtime/evolve/polycube_map.h"

#include <cstddef>
#include <vector>

namespace fgsg::rt::evolve {

struct StretchSummary {
  size_t cells = 0;  // how many cells were measured
  // Nearest-rank percentiles of the cells' stretch (the k-th smallest, k = ceil(q * cells));
  // all 1 when no cell was measured.
  double median = 1, p95 = 1, max = 1;
};

// The stretch of one cell from its four mapped corners: corner[b][a] is the image of the
// cell's corner (a, b) in {0,1}^2 (a along the face-let's u, b along v).
double cellStretch(const Vec3 (&corner)[2][2]);

// The stretch of the n x n cells on face-let f into out[row * n + column].
void faceletStretch(const PolycubeMap& map, size_t facelet, int n, double* out);

// Every cell's stretch for an n x n pattern on every face-let, in the order face-let, row,
// column (index (f * n + row) * n + column). Throws std::invalid_argument for n < 1.
std::vector<double> patternStretch(const PolycubeMap& map, int n);

StretchSummary summarizeStretch(std::vector<double> stretch);

}  // namespace fgsg::rt::evolve
