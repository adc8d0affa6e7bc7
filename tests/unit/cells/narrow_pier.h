// The narrow pier of the cells tests (narrow_pier_test.cpp, leaning_pier_test.cpp): a
// box x in [0, 1], y in [0, 0.15], z in [0, 0.75] standing on the ground (no bottom
// face), 10 courses of 0.075 high, bricked with bricks 0.4 long and 0.1 deep — longer
// than its narrow faces (0.15) plus the corner's depth. `leanDegrees` shears it so that
// its axis leans that far from up within the plane of its narrow faces (y += z tan:
// the narrow faces stay upright parallelograms, the wide ones tilt) or of its wide
// faces (x += z tan).
#pragma once

#include "runtime/cells/cellular_texture.h"
#include "runtime/cells/generators.h"
#include "tests/unit/cells/rectilinear_mesh.h"

#include <cmath>

namespace fgsg::test {

enum class PierLean { InNarrowFaces, InWideFaces };

struct NarrowPier {
  static constexpr double kLength = 1, kWidth = 0.15, kHeight = 0.75;
  static constexpr double kBrickLength = 0.4, kCourse = 0.075, kDepth = 0.1;
};

inline rt::surface::SurfaceMesh narrowPierMesh(double leanDegrees = 0, PierLean lean = PierLean::InNarrowFaces) {
  auto m = rectilinearMesh({{{0, NarrowPier::kLength}, {0, NarrowPier::kWidth}, {0, NarrowPier::kHeight}}},
                           {{0, 0, 0}}, true);
  const double shear = std::tan(leanDegrees * 3.14159265358979323846 / 180);
  for (rt::Vec3& v : m.vertices) v[lean == PierLean::InNarrowFaces ? 1 : 0] += shear * v.z();
  m.buildTopology();
  return m;
}

// Lays the pier's bricks, every corner, edge and face in order.
inline void layPierBricks(rt::cells::CellularTexture& tex) {
  for (rt::cells::FeatureRef f : tex.order())
    rt::cells::layBricks(tex, f, {NarrowPier::kBrickLength, NarrowPier::kCourse, NarrowPier::kDepth});
}

}  // namespace fgsg::test
