#include "runtime/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fgsg::rt {

namespace {

std::array<float, 3> bound(const MeshArray<float>& p, bool lower) {
  if (p.empty()) return {0.0f, 0.0f, 0.0f};
  const float init = lower ? std::numeric_limits<float>::infinity()
                           : -std::numeric_limits<float>::infinity();
  std::array<float, 3> b{init, init, init};
  for (size_t i = 0; i < p.size(); i += 3)
    for (int a = 0; a < 3; ++a) b[a] = lower ? std::min(b[a], p[i + a]) : std::max(b[a], p[i + a]);
  return b;
}

}  // namespace

std::array<float, 3> Mesh::boundsMin() const { return bound(positions, true); }
std::array<float, 3> Mesh::boundsMax() const { return bound(positions, false); }

void Mesh::computeNormals() {
  // Accumulate in double: the unnormalised cross product weights each face by its area.
  std::vector<double> acc(positions.size(), 0.0);
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const float* a = &positions[3 * size_t(indices[t])];
    const float* b = &positions[3 * size_t(indices[t + 1])];
    const float* c = &positions[3 * size_t(indices[t + 2])];
    const double e1[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
    const double e2[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) acc[3 * size_t(indices[t + k]) + d] += n[d];
  }
  normals.assign(positions.size(), 0.0f);
  for (size_t v = 0; v < acc.size(); v += 3) {
    const double len = std::sqrt(acc[v] * acc[v] + acc[v + 1] * acc[v + 1] + acc[v + 2] * acc[v + 2]);
    if (len > 0.0) {
      for (int d = 0; d < 3; ++d) normals[v + d] = float(acc[v + d] / len);
    } else {
      normals[v + 2] = 1.0f;  // an isolated or degenerate vertex still gets a unit normal
    }
  }
}

}  // namespace fgsg::rt
