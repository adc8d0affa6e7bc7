// Continuous model synthesis against the thesis's Table 4.1 (Merrell 2009: input and
// output polygons and minutes per result, on 2009 hardware). For each example of
// examples/synthesis/continuous/ the box grows (x and z doubled from the case's start)
// until the output has at least the table's output polygons (whole faces), then that
// run is timed: best of `reps` wall times. One JSON object per line:
// "size" is fgsg synth's --size: width, depth, height.
//   {"bench":"continuous","case":"houses","example_polygons":7,"table_input":39,
//    "output_polygons":1911,"table_output":1908,"seconds":0.21,"table_seconds":78,
//    "speedup":371, ...}
// Usage: bench_continuous_synthesis [--quick]  (quick: one rep, for a smoke run)
#include "bench/bench_clock.h"
#include "runtime/synthesis/continuous/continuous.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace fgsg::rt::synthesis::continuous;

namespace {

struct Case {
  const char* name;       // Table 4.1's row
  const char* file;       // under examples/synthesis/continuous/
  std::array<double, 3> size;  // the starting box (grown along `grow` until the output is big enough)
  std::array<bool, 3> grow;
  bool onGround;
  double fill;
  std::vector<FixedWidth> fixed;
  std::vector<FixedWidth> planeStep;  // every N-th plane of a steep slope (its header's second command)
  int connect;
  int tableInput, tableOutput;
  double tableMinutes;
};

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int reps = quick ? 1 : 3;
  const std::vector<Case> cases = {
      // The examples' own settings (their headers); the box starts small and grows.
      {"houses", "houses.obj", {16, 10, 16}, {true, false, true}, true, 0.5, {}, {}, 0, 39, 1908, 1.3},
      {"terrain", "terrain.obj", {12, 6, 12}, {true, false, true}, true, 0.7, {},
       {{{2, 1, 0}, 2}, {{-2, 1, 0}, 2}, {{0, 1, 2}, 2}, {{0, 1, -2}, 2}}, 0, 22, 922, 0.5},
      {"arches", "arches.obj", {30, 12, 24}, {true, false, true}, false, 0.9, {{{0, 1, 0}, 4}, {{0, 0, 1}, 2}}, {}, 0, 20, 1002, 0.5},
      {"pentagons", "pentagons.obj", {16, 14, 16}, {true, false, true}, true, 0.7, {}, {}, 0, 33, 2004, 1.1},
      {"roads", "roads.obj", {16, 2, 16}, {true, false, true}, true, 0.5, {},
       {{{1, 2, 0}, 4}, {{-1, 2, 0}, 4}, {{0, 2, 1}, 4}, {{0, 2, -1}, 4}}, 0, 126, 6888, 0.2},
      // Grown from one seed (its header) only up to about 30 x 30: larger boxes contradict.
      {"plumbing", "pipes.obj", {16, 16, 2}, {true, true, false}, false, 0.5, {}, {}, 0, 282, 7422, 0.8},
  };
  for (const Case& c : cases) {
    ExampleSolid ex;
    std::string err;
    const std::string path = std::string(FGSG_SOURCE_DIR) + "/examples/synthesis/continuous/" + c.file;
    if (!loadExampleSolid(path, ex, err)) {
      std::printf("{\"bench\":\"continuous\",\"case\":\"%s\",\"error\":\"%s\"}\n", c.name, err.c_str());
      continue;
    }
    ContinuousOptions o;
    o.size = c.size;
    o.onGround = c.onGround;
    o.fill = c.fill;
    o.fixedWidth = c.fixed;
    o.planeStep = c.planeStep;
    o.growSeeds = c.connect;
    o.seed = 1;
    ContinuousResult r;
    for (int grow = 0; grow < 24; ++grow) {
      r = synthesizeContinuous(ex, o);
      if (!r.ok || r.stats.outputPolygons >= size_t(c.tableOutput)) break;
      for (int k = 0; k < 3; ++k)
        if (c.grow[size_t(k)]) o.size[size_t(k)] = std::round(o.size[size_t(k)] * 1.25);
    }
    if (!r.ok) {
      std::printf("{\"bench\":\"continuous\",\"case\":\"%s\",\"error\":\"%s\"}\n", c.name, r.error.c_str());
      continue;
    }
    double best = 1e30;
    for (int k = 0; k < reps; ++k) {
      const auto t = std::chrono::steady_clock::now();
      r = synthesizeContinuous(ex, o);
      best = std::min(best, fgsg::bench::secondsSince(t));
    }
    const double table = c.tableMinutes * 60;
    std::printf("{\"bench\":\"continuous\",\"case\":\"%s\",\"example_polygons\":%d,\"table_input\":%d,"
                "\"size\":[%g,%g,%g],\"vertices\":%zu,\"labels\":%d,\"output_polygons\":%zu,\"parts\":%zu,"
                "\"table_output\":%d,\"seconds\":%.4f,\"table_seconds\":%.0f,\"speedup\":%.0f,"
                "\"compile_seconds\":%.4f,\"assign_seconds\":%.4f,\"surface_seconds\":%.4f}\n",
                c.name, r.stats.exampleFaces, c.tableInput, o.size[0], o.size[2], o.size[1], r.stats.vertices,
                r.stats.labels, r.stats.outputPolygons, r.stats.parts, c.tableOutput, best, table, table / best,
                r.stats.compileSeconds, r.stats.assignSeconds, r.stats.surfaceSeconds);
    std::fflush(stdout);
  }
  return 0;
}
