#include "runtime/synthesis/continuous/perturb.h"

#include "runtime/synthesis/random.h"

#include <algorithm>

namespace fgsg::rt::synthesis::continuous {

void perturbParts(Mesh& mesh, const std::vector<uint32_t>& vertexPart, std::vector<std::vector<std::array<double, 3>>>& faces,
                  const std::vector<uint32_t>& facePart, uint32_t parts, double amount, uint64_t seed) {
  const size_t n = mesh.vertexCount();
  struct Box {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  };
  std::vector<Box> box(parts);
  for (size_t v = 0; v < n; ++v) {
    Box& b = box[vertexPart[v]];
    for (int c = 0; c < 2; ++c) {
      const double x = mesh.positions[3 * v + (c == 0 ? 0 : 2)];
      b.lo[c] = std::min(b.lo[c], x);
      b.hi[c] = std::max(b.hi[c], x);
    }
  }
  // Parts in order; each move checked against the others as they stand by then.
  Rng rng(seed ^ 0x7065727475726221ULL);
  std::vector<std::array<double, 2>> move(box.size(), {0, 0});
  auto overlaps = [&](size_t p, const Box& b) {
    for (size_t q = 0; q < box.size(); ++q)
      if (q != p && b.lo[0] < box[q].hi[0] && box[q].lo[0] < b.hi[0] && b.lo[1] < box[q].hi[1] && box[q].lo[1] < b.hi[1])
        return true;
    return false;
  };
  for (size_t p = 0; p < box.size(); ++p) {
    const double dx = (2 * rng.uniform() - 1) * amount, dz = (2 * rng.uniform() - 1) * amount;
    for (double scale : {1.0, 0.5, 0.25}) {
      Box b = box[p];
      const double d[2] = {dx * scale, dz * scale};
      for (int c = 0; c < 2; ++c) b.lo[c] += d[c], b.hi[c] += d[c];
      if (overlaps(p, b)) continue;
      box[p] = b;
      move[p] = {d[0], d[1]};
      break;
    }
  }
  for (size_t v = 0; v < n; ++v) {
    mesh.positions[3 * v] = float(mesh.positions[3 * v] + move[vertexPart[v]][0]);
    mesh.positions[3 * v + 2] = float(mesh.positions[3 * v + 2] + move[vertexPart[v]][1]);
  }
  for (size_t f = 0; f < faces.size(); ++f)
    for (auto& q : faces[f]) q[0] += move[facePart[f]][0], q[2] += move[facePart[f]][1];
}

}  // namespace fgsg::rt::synthesis::continuous
