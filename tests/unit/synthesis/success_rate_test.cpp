// Success rate over 100 seeds per example, whole grid (Algorithm 3.1) and with blocks
// (3.4), printed and held above thresholds measured with margin. Every success is
// checker-clean.
#include "test_helpers.h"

#include <cstdio>

using namespace synth_test;

TEST_CASE("success rate over 100 seeds per example", "[synthesis][success-rate]") {
  struct Case {
    const char* file;
    GridSize size;
    double minWhole, minBlocks;  // measured 1.00 / 1.00 for all; margins below
  } cases[] = {
      {"castle.txt", {30, 30, 6}, 0.9, 0.99},  {"city.txt", {30, 30, 5}, 0.9, 0.99},
      {"landscape.txt", {30, 30, 6}, 0.9, 0.99}, {"roads.json", {30, 30, 1}, 0.9, 0.99},
      {"flowers.png", {30, 30, 1}, 0.9, 0.99},
  };
  for (const auto& c : cases) {
    Example ex = load(c.file);
    for (int blocks = 0; blocks < 2; ++blocks) {
      int ok = 0;
      for (uint64_t seed = 1; seed <= 100; ++seed) {
        SynthesisOptions o;
        o.size = c.size;
        o.seed = seed;
        if (blocks) o.block = {10, 10, 10};
        SynthesisResult r = synthesize(ex, o);
        const bool good = r.ok && r.consistent && r.stats.blocksFailed == 0;
        if (r.consistent) CHECK(checkModel(r.labels, ex, specFor(o)).empty());
        ok += good;
      }
      std::printf("success rate %-14s %dx%dx%d %-6s %3d/100\n", c.file, c.size.nx, c.size.ny, c.size.nz,
                  blocks ? "blocks" : "whole", ok);
      CHECK(ok >= int((blocks ? c.minBlocks : c.minWhole) * 100));
    }
  }
}
