// Which optional vertex attributes a mesh writer stores, and how colours are stored:
// one rule for the GLB, OBJ and PLY writers.
#pragma once

#include "runtime/mesh.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::io {

inline bool hasNormals(const Mesh& m) { return m.normals.size() == m.positions.size(); }
inline bool hasColors(const Mesh& m) { return !m.colors.empty() && m.colors.size() == m.positions.size(); }

// Colours in files are in [0,1]; a colour that is not finite is stored as 0.
inline float clamp01(float c) { return std::isfinite(c) ? std::clamp(c, 0.0f, 1.0f) : 0.0f; }

}  // namespace fgsg::rt::io
