// Plane directions of continuous model synthesis (Merrell §4.5): every face normal of the
// example is a small integer vector, so the output's planes a·x = k·step (lattice units)
// meet in rational points that are compared exactly, and four or more planes meet where
// the lattice puts them (§4.5.8) instead of nowhere.
//
// A "sector" is one region of the central arrangement of a set of directions E: the
// directions r with a fixed sign of a_e·r for every e in E, written as a bit mask over
// the global direction indices (bit e set: a_e·r > 0). A vertex figure (a label) is a set
// of sectors.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace fgsg::rt::synthesis::continuous {

using IVec3 = std::array<int64_t, 3>;
using DVec3 = std::array<double, 3>;

inline int64_t dot(const IVec3& a, const IVec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline IVec3 cross(const IVec3& a, const IVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dotd(const IVec3& a, const DVec3& b) { return double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2]; }
inline bool isZero(const IVec3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

// Divided by the gcd of its components, first non-zero component positive.
IVec3 canonicalDirection(IVec3 a);

// The integer direction (components at most `maxComponent` in size, canonical) within
// `toleranceRadians` of the unit vector n, preferring the smallest components; none when
// no such vector is close enough.
std::optional<IVec3> snapToIntegerDirection(const DVec3& n, int maxComponent, double toleranceRadians);

// Directions perpendicular to `axis` (unit, double), one strictly inside each wedge that
// the planes `around` (all containing `axis`: a_e·axis = 0) cut around it, in angular
// order. `around` empty: one direction (any).
std::vector<DVec3> wedgesAround(const IVec3& axis, const std::vector<IVec3>& around);

// The sign mask over `mask` (indices into dirs) of the direction axis + tiny·r: the sign of
// a_e·axis where it is not zero, else of a_e·r. None when some a_e·r is zero too (r lies
// on plane e: not a direction of any sector).
std::optional<uint32_t> signMaskNear(const std::vector<IVec3>& dirs, uint32_t mask, const IVec3& axis, const DVec3& r);

struct Sector {
  uint32_t signs = 0;  // over the set's directions only
  DVec3 direction{};   // a unit direction strictly inside the sector
};

// Every sector of the central arrangement of the directions in `mask`, each once.
std::vector<Sector> sectorsOf(const std::vector<IVec3>& dirs, uint32_t mask);

}  // namespace fgsg::rt::synthesis::continuous
