// A 7 x 4 house, 3 high, under a hipped roof (apex 1.25 above the eaves, y up), as a
// grammar's Comp pieces would give it: four walls labelled "wall", four roof faces "roof".
// Shared by the shingles test and the coverage test.
#pragma once

#include "runtime/cells/base_mesh_pieces.h"

#include <vector>

namespace fgsg::test {

inline std::vector<rt::cells::LabelledPolygon> hippedHousePieces() {
  using rt::Vec3;
  const double top = 4.25;
  return {{"wall", {Vec3(0, 0, 4), Vec3(7, 0, 4), Vec3(7, 3, 4), Vec3(0, 3, 4)}},
          {"wall", {Vec3(7, 0, 4), Vec3(7, 0, 0), Vec3(7, 3, 0), Vec3(7, 3, 4)}},
          {"wall", {Vec3(7, 0, 0), Vec3(0, 0, 0), Vec3(0, 3, 0), Vec3(7, 3, 0)}},
          {"wall", {Vec3(0, 0, 0), Vec3(0, 0, 4), Vec3(0, 3, 4), Vec3(0, 3, 0)}},
          {"roof", {Vec3(0, 3, 4), Vec3(7, 3, 4), Vec3(5, top, 2), Vec3(2, top, 2)}},
          {"roof", {Vec3(7, 3, 4), Vec3(7, 3, 0), Vec3(5, top, 2)}},
          {"roof", {Vec3(7, 3, 0), Vec3(0, 3, 0), Vec3(2, top, 2), Vec3(5, top, 2)}},
          {"roof", {Vec3(0, 3, 0), Vec3(0, 3, 4), Vec3(2, top, 2)}}};
}

}  // namespace fgsg::test
