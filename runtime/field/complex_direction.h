// A tangent-plane vector as a complex number, as the heat method (geodesics.cpp) and the
// exponential map (exp_map.cpp) carry directions from frame to frame: a Rot2 turns one by
// a product. One definition for both, where private copies would clash in a unity batch.
#pragma once

#include "runtime/field/tangent_frames.h"

#include <complex>

namespace fgsg::rt::field {

// (x, y) in a frame's coordinates as x + i y.
inline std::complex<double> toComplex(const Vec2& v) { return {v.x(), v.y()}; }

// z scaled to length 1; `fallback` where z is 0 and has no direction.
inline std::complex<double> unitOr(const std::complex<double>& z, const std::complex<double>& fallback) {
  const double len = std::abs(z);
  return len > 0 ? z / len : fallback;
}

}  // namespace fgsg::rt::field
