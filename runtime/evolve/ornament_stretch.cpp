#include "runtime/evolve/ornament_stretch.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace fgsg::rt::evolve {

double cellStretch(const Vec3 (&corner)[2][2]) {
  const double sides[4] = {(corner[0][1] - corner[0][0]).norm(), (corner[1][1] - corner[0][1]).norm(),
                           (corner[1][0] - corner[1][1]).norm(), (corner[0][0] - corner[1][0]).norm()};
  const double longest = *std::max_element(sides, sides + 4), shortest = *std::min_element(sides, sides + 4);
  if (shortest > 0) return longest / shortest;
  return longest > 0 ? std::numeric_limits<double>::infinity() : 1.0;  // a cell collapsed to a point is not streaked
}

void faceletStretch(const PolycubeMap& map, size_t facelet, int n, double* out) {
  const size_t side = size_t(n);
  // The (n+1)^2 lattice points of the face-let's cells, mapped once each.
  std::vector<Vec3> at((side + 1) * (side + 1));
  for (size_t j = 0; j <= side; ++j)
    for (size_t i = 0; i <= side; ++i) at[j * (side + 1) + i] = map.map(facelet, double(i) / n, double(j) / n).position;
  for (size_t row = 0; row < side; ++row)
    for (size_t col = 0; col < side; ++col) {
      const size_t j = side - 1 - row;  // row 0 at the top: b from (n-1-row)/n
      const Vec3 corner[2][2] = {{at[j * (side + 1) + col], at[j * (side + 1) + col + 1]},
                                 {at[(j + 1) * (side + 1) + col], at[(j + 1) * (side + 1) + col + 1]}};
      out[row * side + col] = cellStretch(corner);
    }
}

std::vector<double> patternStretch(const PolycubeMap& map, int n) {
  if (n < 1) throw std::invalid_argument("patternStretch: the pattern needs at least one cell a side");
  const size_t perFacelet = size_t(n) * size_t(n);
  std::vector<double> stretch(map.facelets().size() * perFacelet);
  tbb::parallel_for(size_t(0), map.facelets().size(),
                    [&](size_t f) { faceletStretch(map, f, n, stretch.data() + f * perFacelet); });
  return stretch;
}

StretchSummary summarizeStretch(std::vector<double> stretch) {
  StretchSummary s;
  s.cells = stretch.size();
  if (stretch.empty()) return s;
  std::sort(stretch.begin(), stretch.end());
  // In whole numbers: k = ceil(percent * cells / 100), at least 1.
  const auto rank = [&](size_t percent) { return stretch[std::max<size_t>((percent * stretch.size() + 99) / 100, 1) - 1]; };
  s.median = rank(50);
  s.p95 = rank(95);
  s.max = stretch.back();
  return s;
}

}  // namespace fgsg::rt::evolve
