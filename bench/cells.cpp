// Feature-based cellular texturing (Legakis et al. 2001, issue #15): cells per second on
// examples/assets/brick_building.obj (a block with three windows and an arched door) with
// examples/brick_building.fgsg's pattern tree in C++: base mesh features, occupancy maps,
// corners -> edges -> faces, the overlap guard. One JSON line:
//   {"bench":"cells","cells":N,"seconds":S,"cells_per_s":...,"triangles_per_s":...}
// (12 output triangles per box cell; best of `reps` runs, one thread.) The paper gives no
// timings; the target is >= 1 M cells/s.
// Usage: bench_cells [--quick] [--digest]
// --digest adds "digest": a hash of every cell's feature, corners and profile rounded to
// 1e-9, so a speed-up can be checked to leave the cells as they were.
#include "runtime/cells/base_mesh_file.h"
#include "runtime/cells/generators.h"
#include "tests/unit/cells/brick_building_tree.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstdint>
#include <cstring>

using namespace fgsg::rt::cells;

namespace {
// FNV-1a over the cells' features and their corners' coordinates rounded to 1e-9.
uint64_t cellsDigest(const std::vector<Cell>& cells) {
  uint64_t h = 1469598103934665603ull;
  auto mix = [&](int64_t v) {
    for (int b = 0; b < 8; ++b) h = (h ^ uint64_t((v >> (8 * b)) & 0xff)) * 1099511628211ull;
  };
  for (const Cell& c : cells) {
    mix(int64_t(c.feature.kind)), mix(c.feature.index), mix(int64_t(c.profile.size()));
    for (const auto& v : c.vertices())
      for (int k = 0; k < 3; ++k) mix(std::llround(v[k] * 1e9));
  }
  return h;
}
}  // namespace

int main(int argc, char** argv) {
  bool quick = false, digest = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    if (std::strcmp(argv[i], "--digest") == 0) digest = true;
  }
  uint64_t hash = 0;
  const LabelledMesh lm = readBaseMeshObj(FGSG_SOURCE_DIR "/examples/assets/brick_building.obj");
  double best = 1e300, featureSeconds = 0;
  size_t cells = 0;
  for (int rep = 0; rep < (quick ? 2 : 10); ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    CellularTexture tex(lm.mesh, buildLabelledFeatureMesh(lm));
    const auto t1 = std::chrono::steady_clock::now();
    fgsg::test::layBrickBuilding(tex);
    const auto t2 = std::chrono::steady_clock::now();
    cells = tex.cells().size();
    if (digest && rep == 0) hash = cellsDigest(tex.cells());
    best = std::min(best, std::chrono::duration<double>(t2 - t1).count());
    featureSeconds = std::chrono::duration<double>(t1 - t0).count();
  }
  std::printf("{\"bench\":\"cells\",\"cells\":%zu,\"seconds\":%.6f,\"cells_per_s\":%.0f,\"triangles_per_s\":%.0f,"
              "\"features_seconds\":%.6f",
              cells, best, cells / best, 12.0 * cells / best, featureSeconds);
  if (digest) std::printf(",\"digest\":\"%016llx\"", (unsigned long long)hash);
  std::printf("}\n");
}
