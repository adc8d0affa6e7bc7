// Small planar helpers shared by parametrization, validation and packing.
#pragma once

#include "runtime/atlas/atlas.h"

namespace fgsg::rt::atlas {

// Twice the signed area of triangle (a, b, c): positive when it runs counter-clockwise.
inline double twiceSignedArea(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}
inline double twiceSignedArea(const std::array<Vec2, 3>& t) { return twiceSignedArea(t[0], t[1], t[2]); }

}  // namespace fgsg::rt::atlas
