// Mesh files (glTF, OBJ, PLY) store coordinates as 32-bit floats: a transform that is
// finite in double precision can still place vertices beyond ±3.4e38, which would be
// written as inf. Engines check every instance with this before placing it.
#pragma once

#include "runtime/scope.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace fgsg::rt {

// The largest magnitude any coordinate of the unit box's image under `t` reaches (the
// corners bound it: the map is affine); infinity when some value is not finite.
inline double unitBoxReach(const Mat4& t) {
  double reach = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector4d p = t * Eigen::Vector4d(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1, 1.0);
    for (int d = 0; d < 3; ++d) {
      const double a = std::fabs(p[d]);
      if (!std::isfinite(a)) return std::numeric_limits<double>::infinity();
      reach = std::max(reach, a);
    }
  }
  return reach;
}

// True when every vertex of an instance placed by `t` fits a 32-bit float.
inline bool unitBoxFitsFloat(const Mat4& t) { return unitBoxReach(t) <= double(FLT_MAX); }

// The quick test engines run first (a turtle places millions of segments): a coordinate
// of the image ranges from its translation plus the negative entries of its row to the
// translation plus the positive ones, so 12 additions bound it. True when that bound is
// well inside float range (or NaN: false); unitBoxReach decides the rest exactly.
inline bool unitBoxClearlyFitsFloat(const Mat4& t) {
  double reach = 0.0;
  bool finite = true;
  for (int d = 0; d < 3; ++d) {
    double hi = t(d, 3), lo = t(d, 3);
    for (int k = 0; k < 3; ++k) {
      hi += std::max(t(d, k), 0.0);  // NaN stays NaN (std::max returns its first)
      lo += std::min(t(d, k), 0.0);
    }
    finite = finite && std::isfinite(hi) && std::isfinite(lo);  // a NaN entry makes both NaN
    reach = std::max(reach, std::max(std::fabs(hi), std::fabs(lo)));
  }
  return finite && reach < 0.5 * double(FLT_MAX);
}

}  // namespace fgsg::rt
