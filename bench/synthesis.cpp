// Discrete model synthesis benchmark. One JSON object per line:
//   {"bench":"synthesis","case":...,"size":[nx,ny,nz],"labels":k,...}
// Cases: cells/s for 40x40x10 and 200x200x20 with ~100 labels (whole grid = Algorithm 3.1,
// blocks = Algorithm 3.4), success rates over seeds with and without blocks for the
// 109-label boxes and the bundled examples, peak memory (VmHWM, process-wide so it only
// grows) and the solver's own bytes (catalog_bytes: catalog + base domains + site graph +
// transition rows). Times are the best of `reps` runs (the machine may be shared).
// Usage: bench_synthesis [--quick | --small | --orientations [SEEDS]]
// (--orientations also runs examples/synthesis/summer_like.json, a 2D tile set, at 100x100.)
#include "runtime/synthesis/checker.h"
#include "runtime/synthesis/synthesis.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

using namespace fgsg::rt::synthesis;

namespace {

long vmHwmKb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
  return -1;
}

// ~100 labels: boxes of 4 materials, each box cell labelled by material and by where it
// lies in its box (min/middle/max along each axis: 27 classes) = 108 labels + empty. The
// boxes are enclosed by empty space, so models of any size exist (thm 3.2.1), and middle
// cells repeat, so boxes stretch to any size >= 3.
Example boxesExample() {
  Example ex;
  const GridSize s{30, 30, 12};
  LabelGrid g(s, 0);
  ex.labels.push_back({".", "", 0, false, false, {}, 1.0, true, false});
  for (int m = 0; m < 4; ++m)
    for (int c = 0; c < 27; ++c) {
      Piece p;
      p.name = "m" + std::to_string(m) + "c" + std::to_string(c);
      p.asset = "cube";
      ex.labels.push_back(p);
    }
  ex.emptyLabel = 0;
  int m = 0;
  for (int bz = 1; bz + 4 < s.nz; bz += 6)
    for (int by = 1; by + 4 < s.ny; by += 6)
      for (int bx = 1; bx + 4 < s.nx; bx += 6, m = (m + 1) % 4)
        for (int z = 0; z < 4; ++z)
          for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
              auto cls = [](int v) { return v == 0 ? 0 : v == 3 ? 2 : 1; };
              g.at(bx + x, by + y, bz + z) = 1 + m * 27 + cls(x) + 3 * cls(y) + 9 * cls(z);
            }
  ex.grid = g;
  for (auto& p : ex.labels) p.weight = -1;
  computeAdjacencyFromGrid(ex);
  ex.labels[0].weight *= 0.05;  // favour objects over empty space
  return ex;
}

void emit(const char* name, const Example& ex, const SynthesisOptions& o, int reps, const char* extra = "") {
  double best = 1e9, total = 0;
  SynthesisResult r;
  int ok = 0;
  for (int i = 0; i < reps; ++i) {
    SynthesisOptions oo = o;
    oo.seed = o.seed + uint64_t(i);
    r = synthesize(ex, oo);
    ok += r.ok && r.consistent;
    best = std::min(best, r.stats.seconds);
    total += r.stats.seconds;
  }
  const double cells = double(o.size.count());
  std::printf(
      "{\"bench\":\"synthesis\",\"case\":\"%s\",\"size\":[%d,%d,%d],\"labels\":%d,\"block\":%d,"
      "\"reps\":%d,\"ok\":%d,\"best_ms\":%.3f,\"mean_ms\":%.3f,"
      "\"cells_per_s\":%.0f,\"assignments_per_s\":%.0f,\"blocks\":%d,\"blocks_failed\":%d,"
      "\"pops_per_assignment\":%.2f,\"support_misses_per_pop\":%.4f,\"catalog_bytes\":%zu,"
      "\"bytes_per_cell\":%.1f,\"vmhwm_kb\":%ld%s}\n",
      name, o.size.nx, o.size.ny, o.size.nz, ex.labelCount(), o.block[0],
      reps, ok, best * 1e3, total / reps * 1e3,
      cells / best, double(r.stats.assignments) / r.stats.seconds, r.stats.blocks, r.stats.blocksFailed,
      double(r.stats.propagationSteps) / double(std::max<uint64_t>(1, r.stats.assignments)),
      double(r.stats.supportMisses) / double(std::max<uint64_t>(1, r.stats.propagationSteps)),
      r.stats.catalogBytes, double(r.stats.catalogBytes) / cells, vmHwmKb(), extra);
  std::fflush(stdout);
}

void successRate(const char* file, const Example& ex, GridSize size, int seeds, int block) {
  int ok = 0, allBlocks = 0, clean = 0;
  double secs = 0;
  for (int s = 1; s <= seeds; ++s) {
    SynthesisOptions o;
    o.size = size;
    o.seed = uint64_t(s);
    o.block = {block, block, block};
    SynthesisResult r = synthesize(ex, o);
    secs += r.stats.seconds;
    ok += r.ok && r.consistent;
    allBlocks += r.ok && r.stats.blocksFailed == 0;
    if (r.consistent) {
      CheckSpec spec;
      clean += checkModel(r.labels, ex, spec).empty();
    }
  }
  std::printf(
      "{\"bench\":\"synthesis\",\"case\":\"success_rate\",\"example\":\"%s\",\"size\":[%d,%d,%d],"
      "\"block\":%d,\"seeds\":%d,\"success\":%.2f,\"all_blocks_ok\":%.2f,\"checker_clean\":%d,\"mean_ms\":%.3f}\n",
      file, size.nx, size.ny, size.nz, block, seeds, double(ok) / seeds, double(allBlocks) / seeds, clean,
      secs / seeds * 1e3);
  std::fflush(stdout);
}

// The example with its axes permuted: new axis i is old axis perm[i] (grid, adjacency
// rules, borders). Symmetry maps are dropped (no case here uses them).
Example permuted(const Example& ex, std::array<int, 3> perm) {
  Example out = ex;
  std::array<int, 3> inv{};
  for (int i = 0; i < 3; ++i) inv[size_t(perm[size_t(i)])] = i;
  for (int i = 0; i < 3; ++i) out.allowed[size_t(i)] = ex.allowed[size_t(perm[size_t(i)])];
  for (int f = 0; f < 6; ++f) {
    const int to = 2 * inv[size_t(f / 2)] + f % 2;
    out.border.outside[size_t(to)] = ex.border.outside[size_t(f)];
    out.border.fixed[size_t(to)] = ex.border.fixed[size_t(f)];
    out.border.only[size_t(to)] = ex.border.only[size_t(f)];
  }
  out.mirrorX.clear(), out.mirrorY.clear(), out.rot90.clear();
  if (ex.grid) {
    const GridSize n = ex.grid->size();
    const int ext[3] = {n.nx, n.ny, n.nz};
    LabelGrid g(GridSize{ext[perm[0]], ext[perm[1]], ext[perm[2]]}, 0);
    for (int z = 0; z < n.nz; ++z)
      for (int y = 0; y < n.ny; ++y)
        for (int x = 0; x < n.nx; ++x) {
          const int c[3] = {x, y, z};
          g.at(c[perm[0]], c[perm[1]], c[perm[2]]) = ex.grid->at(x, y, z);
        }
    out.grid = g;
  }
  return out;
}

// First-attempt success over seeds in each of the six axis orders: the default order
// must not depend on which axis is up (#18).
void orientations(const char* file, const Example& ex, GridSize size, int seeds, CellOrder order) {
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int ext[3] = {size.nx, size.ny, size.nz};
  for (const auto& p : perms) {
    const Example e = permuted(ex, {p[0], p[1], p[2]});
    int ok = 0;
    double secs = 0;
    for (int s = 1; s <= seeds; ++s) {
      SynthesisOptions o;
      o.size = {ext[p[0]], ext[p[1]], ext[p[2]]};
      o.seed = uint64_t(s);
      o.order = order;
      const SynthesisResult r = synthesize(e, o);
      ok += r.ok && r.consistent;
      secs += r.stats.seconds;
    }
    std::printf(
        "{\"bench\":\"synthesis\",\"case\":\"orientation\",\"example\":\"%s\",\"axes\":\"%c%c%c\","
        "\"size\":[%d,%d,%d],\"order\":\"%s\",\"seeds\":%d,\"first_attempt\":%.2f,\"mean_ms\":%.3f}\n",
        file, "xyz"[p[0]], "xyz"[p[1]], "xyz"[p[2]], ext[p[0]], ext[p[1]], ext[p[2]],
        order == CellOrder::kScanline ? "scanline" : "entropy", seeds, double(ok) / seeds, secs / seeds * 1e3);
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--orientations") == 0) {
    const int seeds = argc > 2 ? std::atoi(argv[2]) : 100;
    orientations("boxes", boxesExample(), {40, 40, 10}, seeds, CellOrder::kScanline);
    struct { const char* file; GridSize size; } cases[] = {
        {"castle.txt", {40, 40, 6}}, {"city.txt", {40, 40, 5}}, {"landscape.txt", {40, 40, 6}}};
    for (const auto& c : cases) {
      Example ex;
      Diagnostics d;
      if (!loadExample(std::string(FGSG_SOURCE_DIR) + "/examples/synthesis/" + c.file, ex, d)) {
        std::fprintf(stderr, "%s", formatDiagnostics(d).c_str());
        return 1;
      }
      orientations(c.file, ex, c.size, seeds, CellOrder::kScanline);
      orientations(c.file, ex, c.size, seeds, CellOrder::kMinEntropy);
    }
    // A 2D tile set after WFC's Summer at 100x100: its rules hold under every symmetry of
    // the square, so one orientation says it all.
    Example summer;
    Diagnostics d;
    if (!loadExample(std::string(FGSG_SOURCE_DIR) + "/examples/synthesis/summer_like.json", summer, d)) {
      std::fprintf(stderr, "%s", formatDiagnostics(d).c_str());
      return 1;
    }
    for (CellOrder order : {CellOrder::kScanline, CellOrder::kMinEntropy}) {
      int ok = 0;
      double secs = 0;
      uint64_t backtracks = 0, repairs = 0;
      for (int s = 1; s <= seeds; ++s) {
        SynthesisOptions o;
        o.size = {100, 100, 1};
        o.seed = uint64_t(s);
        o.order = order;
        const SynthesisResult r = synthesize(summer, o);
        ok += r.ok && r.consistent;
        secs += r.stats.seconds;
        backtracks += r.stats.backtracks;
        repairs += r.stats.repairs;
      }
      std::printf("{\"bench\":\"synthesis\",\"case\":\"tile_set\",\"example\":\"summer_like.json\","
                  "\"size\":[100,100,1],\"order\":\"%s\",\"seeds\":%d,\"first_attempt\":%.2f,"
                  "\"mean_ms\":%.3f,\"mean_backtracks\":%.1f,\"mean_repairs\":%.1f}\n",
                  order == CellOrder::kScanline ? "scanline" : "entropy", seeds, double(ok) / seeds,
                  secs / seeds * 1e3, double(backtracks) / seeds, double(repairs) / seeds);
    }
    return 0;
  }
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const bool only40 = argc > 1 && std::strcmp(argv[1], "--small") == 0;
  const Example boxes = boxesExample();
  SynthesisOptions o;
  o.seed = 1;
  o.size = {40, 40, 10};
  // Whole grid (Algorithm 3.1) and blocks (3.4).
  emit("boxes_whole", boxes, o, quick ? 3 : 10);
  o.block = {10, 10, 10};
  emit("boxes_blocks", boxes, o, quick ? 3 : 10);
  o.order = CellOrder::kMinEntropy;
  o.block = {0, 0, 0};
  emit("boxes_whole_min_entropy", boxes, o, quick ? 2 : 5);
  o.order = CellOrder::kScanline;
  if (only40) return 0;
  o.size = {200, 200, 20};
  emit("boxes_whole", boxes, o, quick ? 1 : 3);
  o.block = {10, 10, 10};
  emit("boxes_blocks", boxes, o, quick ? 1 : 2);
  o.block = {20, 20, 20};
  emit("boxes_blocks", boxes, o, 1);

  const int seeds = quick ? 20 : 100;
  successRate("boxes", boxes, {40, 40, 10}, seeds, 0);
  successRate("boxes", boxes, {40, 40, 10}, seeds, 10);
  struct { const char* file; GridSize size; } examples[] = {
      {"castle.txt", {40, 40, 6}}, {"city.txt", {40, 40, 5}}, {"landscape.txt", {40, 40, 6}},
      {"roads.json", {40, 40, 1}}, {"flowers.png", {40, 40, 1}}};
  for (const auto& e : examples) {
    Example ex;
    Diagnostics d;
    if (!loadExample(std::string(FGSG_SOURCE_DIR) + "/examples/synthesis/" + e.file, ex, d)) {
      std::fprintf(stderr, "%s", formatDiagnostics(d).c_str());
      return 1;
    }
    successRate(e.file, ex, e.size, seeds, 0);
    successRate(e.file, ex, e.size, seeds, 10);
  }
  return 0;
}
