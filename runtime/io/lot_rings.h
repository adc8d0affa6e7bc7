// A lot's rings checked and oriented, for every reader that makes lots (GeoJSON polygons,
// mesh faces): no two edges may touch or cross except neighbours at their shared point (so
// holes lie strictly inside the outer ring and strictly outside each other), and no ring
// may have zero area. The outer ring comes out counter-clockwise, holes clockwise. Messages
// name the lot, the ring and the offending points as the file wrote them, in each reader's
// words (LotMessages).
#pragma once

#include "runtime/lot.h"

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace fgsg::rt {

// The most points one lot (outer ring and holes together) may have: far above any real
// lot, and low enough that the edge checks, quadratic at worst, stay under a second.
constexpr size_t kMaxLotPoints = 20'000;

// Coordinates in metres beyond this are no place on Earth, and would overflow the area sums.
constexpr double kMaxLotMetres = 1e9;

// One ring as read: its points in metres (x east, y north), where each stood in the file
// (its position in the ring as written, before duplicates were dropped), and the same
// points as the file wrote them, for messages (degrees, or a mesh corner's x y z).
struct LotRing {
  std::vector<Eigen::Vector2d> xy;
  std::vector<size_t> index;
  std::vector<Eigen::Vector3d> file;
};

// How messages name a lot and its points. The defaults are the GeoJSON reader's:
//   lots.geojson: feature 3 (id "L4"), ring 1 (hole 1): the edge from point 4 (8.5, 47.3) to ...
// a mesh face reads
//   lots.obj: face 12: the edge from corner 4 (1, 0, -2) to ...
struct LotMessages {
  std::string place;                // the lot: "lots.geojson: feature 3 (id "L4"), polygon 1"
  bool namesRings = true;           // ", ring 1 (hole 1)" after the place; off for lots of one ring
  std::string pointNoun = "point";  // what a point is called ("point", "corner")
  int coordinates = 2;              // how many of LotRing::file's coordinates a point shows
  std::string view;                 // after "zero area": how the lot is seen (" seen from above")
};

// "ring 0 (outer)", "ring 2 (hole 2)".
std::string lotRingName(size_t r);

// Checks `rings` (the outer ring first, then the holes; each with at least one point, no
// two consecutive points equal in xy, nor the last and the first) and, when they are
// sound, moves them into lot.outer and lot.holes, oriented (a reversed ring keeps its first
// point first). False with `error` set and `lot` untouched otherwise.
bool checkAndOrientRings(std::vector<LotRing>& rings, const LotMessages& messages, Lot& lot,
                         std::string& error);

}  // namespace fgsg::rt
