// Small planar helpers shared by parametrization, validation and packing.
#pragma once

#include "runtime/atlas/atlas.h"
#include "runtime/planar.h"

namespace fgsg::rt::atlas {

using rt::twiceSignedArea;
inline double twiceSignedArea(const std::array<Vec2, 3>& t) { return twiceSignedArea(t[0], t[1], t[2]); }

}  // namespace fgsg::rt::atlas
