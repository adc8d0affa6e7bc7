// CityEngine's i(asset, upAxisOfGeometry, insertMode) as the transform of an instance: the map
// from the asset's unit box (every asset is normalised into [0,1]^3, runtime/assets.h) to
// the world, given the bounding box the asset had in its file.
//   zUp: the asset is turned -90 degrees about X first, (x, y, z) -> (x, z, -y), so its box
//        is (lo.x, lo.z, -hi.y) .. (hi.x, hi.z, -lo.y) and a unit-box point u lands at
//        (u.x, u.z, 1 - u.y) of the turned box.
//   alignSizeAndPosition: the (turned) box is stretched onto the scope (plain I()).
//   keepSizeAndPosition: the asset keeps its size and its file's position, read in the
//        scope's frame (CityEngine: as s(0,0,0) does): the scope becomes P + axes * lo, size
//        the box's.
//   keepSizeAlignPosition: its size kept, centred on the scope's x and z, its box on y = 0.
#pragma once

#include "runtime/scope.h"

namespace fgsg::rt {

enum class InsertFitMode : uint8_t { AlignSizeAndPosition, KeepSizeAndPosition, KeepSizeAlignPosition };

// The scope the asset fills after the insert (CityEngine sets the shape's scope to it).
inline Scope insertedScope(const Scope& scope, const Vec3& lo, const Vec3& hi, bool zUp, InsertFitMode mode) {
  if (mode == InsertFitMode::AlignSizeAndPosition) return scope;
  const Vec3 turnedLo = zUp ? Vec3(lo.x(), lo.z(), -hi.y()) : lo;
  const Vec3 turnedHi = zUp ? Vec3(hi.x(), hi.z(), -lo.y()) : hi;
  Scope s = scope;
  s.S = turnedHi - turnedLo;
  const Vec3 at = mode == InsertFitMode::KeepSizeAndPosition
                      ? turnedLo
                      : Vec3((scope.S.x() - s.S.x()) / 2, 0.0, (scope.S.z() - s.S.z()) / 2);
  s.P = scope.toWorld(at);
  return s;
}

// The instance's transform: the unit box onto `fitted` (insertedScope), turned for zUp.
inline Mat4 insertTransform(const Scope& fitted, bool zUp) {
  Mat4 t = fitted.unitBoxToWorld();
  if (!zUp) return t;
  Mat4 turn = Mat4::Zero();  // u -> (u.x, u.z, 1 - u.y)
  turn(0, 0) = 1;
  turn(1, 2) = 1;
  turn(2, 1) = -1;
  turn(2, 3) = 1;
  turn(3, 3) = 1;
  return t * turn;
}

}  // namespace fgsg::rt
