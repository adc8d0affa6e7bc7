// Base meshes of a house that several cells tests lay cells on.
#pragma once

#include "runtime/cells/base_mesh_file.h"
#include "runtime/cells/base_mesh_pieces.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace fgsg::test {

// A 7 x 4 house, 3 high, under a hipped roof (apex 1.25 above the eaves, y up), as a
// grammar's Comp pieces would give it: four walls labelled "wall", four roof faces "roof".
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

// The gable wall of a house 6 m wide, 3 m to the eaves, rakes at 30 degrees: apex at
// 3 + 3 tan 30 = 3 + sqrt 3; one face labelled "wall" in the z = 0 plane, y up.
inline rt::cells::LabelledMesh gableWallMesh() {
  std::ostringstream obj;
  obj.precision(17);
  obj << "g wall\nv 0 0 0\nv 6 0 0\nv 6 3 0\nv 3 " << 3 + std::sqrt(3.0) << " 0\nv 0 3 0\nf 1 2 3 4 5\n";
  return rt::cells::parseBaseMeshObj(obj.str(), "gable");
}

}  // namespace fgsg::test
