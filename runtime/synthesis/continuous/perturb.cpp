#include "runtime/synthesis/continuous/perturb.h"

#include "runtime/synthesis/random.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace fgsg::rt::synthesis::continuous {

void perturbParts(Mesh& mesh, std::vector<std::vector<std::array<double, 3>>>& faces, double amount, uint64_t seed) {
  const size_t n = mesh.vertexCount();
  std::vector<uint32_t> up(n);
  std::iota(up.begin(), up.end(), 0);
  auto find = [&](uint32_t a) {
    while (up[a] != a) a = up[a] = up[up[a]];
    return a;
  };
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 1; k < 3; ++k) up[find(mesh.indices[3 * t + size_t(k)])] = find(mesh.indices[3 * t]);
  std::map<uint32_t, size_t> partOf;
  for (uint32_t v = 0; v < n; ++v) partOf.emplace(find(v), partOf.size());
  struct Box {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  };
  std::vector<Box> box(partOf.size());
  for (uint32_t v = 0; v < n; ++v) {
    Box& b = box[partOf[find(v)]];
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
  std::map<std::array<float, 3>, size_t> partAt;
  for (uint32_t v = 0; v < n; ++v) {
    const size_t p = partOf[find(v)];
    partAt[{mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]}] = p;
    mesh.positions[3 * v] = float(mesh.positions[3 * v] + move[p][0]);
    mesh.positions[3 * v + 2] = float(mesh.positions[3 * v + 2] + move[p][1]);
  }
  for (auto& f : faces) {
    auto it = partAt.find({float(f[0][0]), float(f[0][1]), float(f[0][2])});
    if (it == partAt.end()) continue;
    for (auto& q : f) q[0] += move[it->second][0], q[2] += move[it->second][1];
  }
}

}  // namespace fgsg::rt::synthesis::continuous
