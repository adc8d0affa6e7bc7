// Feature-based cellular texturing (Legakis et al. 2001, issue #15): cells per second on
// examples/assets/brick_building.obj (a block with three windows and an arched door) with
// examples/brick_building.fgsg's pattern tree in C++: base mesh features, occupancy maps,
// corners -> edges -> faces, the overlap guard. One JSON line:
//   {"bench":"cells","cells":N,"seconds":S,"cells_per_s":...,"triangles_per_s":...}
// (12 output triangles per box cell; best of `reps` runs, one thread.) The paper gives no
// timings; the target is >= 1 M cells/s.
// Usage: bench_cells [--quick]
#include "runtime/cells/base_mesh_file.h"
#include "runtime/cells/generators.h"
#include "tests/unit/cells/brick_building_tree.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

using namespace fgsg::rt::cells;

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
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
    best = std::min(best, std::chrono::duration<double>(t2 - t1).count());
    featureSeconds = std::chrono::duration<double>(t1 - t0).count();
  }
  std::printf("{\"bench\":\"cells\",\"cells\":%zu,\"seconds\":%.6f,\"cells_per_s\":%.0f,\"triangles_per_s\":%.0f,"
              "\"features_seconds\":%.6f}\n",
              cells, best, cells / best, 12.0 * cells / best, featureSeconds);
}
