// L-system surface patterns (Chan & Hui 2013, issue #14): the genetic algorithm over 2D
// L-systems, on the paper's example tile set (2 loci x 1 cross-section x 4 orientations =
// 8 alleles). One JSON object per line:
//   {"bench":"evolve","case":"generations",...}  GA generations per second: population 100,
//       3x3 rules, patterns of L-system generation 4 (81x81 cells), threshold unreachable so
//       every generation runs; best of `reps` runs; also fitness evaluations per second. On
//       one thread and on all (TBB's default concurrency).
//   {"bench":"evolve","case":"p4",...}  time until the GA finds a pattern with the p4
//       signature and fitness >= the default threshold (same sizes), over `seeds` seeds:
//       converged count, median and slowest seconds.
//   {"bench":"evolve","case":"ornament",...}  ornament triangles per second: a p4 pattern
//       (generation 1, 3x3 cells a face-let) laid on a torus (R 2, r 0.8) through a
//       resolution-8 polycube, with the offset surface's height limit (§5-6.3): the times
//       of the polycube, the offset surface and the ornament itself (best of `reps`).
// The p4 and ornament cases use every core TBB sees (the machine may be shared: compare
// ratios within one run).
// Usage: bench_evolve [--quick] [--seeds N]
#include "runtime/evolve/genetic.h"
#include "runtime/evolve/offset_surface.h"
#include "runtime/evolve/surface_ornament.h"
#include "runtime/surface/procedural.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace fgsg::rt::evolve;

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int seeds = 20;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true, seeds = 5;
    else if (!std::strcmp(argv[i], "--seeds") && i + 1 < argc) seeds = std::max(1, std::atoi(argv[++i]));
    else {
      std::fprintf(stderr, "usage: bench_evolve [--quick] [--seeds N]\n");
      return 2;
    }
  }
  const TileSet tiles = exampleTileSet();

  // Generations per second, on one core and on all.
  for (const int threads : {1, tbb::info::default_concurrency()}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    EvolveOptions o;
    o.population = 100;
    o.ruleSide = 3;
    o.generation = 4;
    o.threshold = 2;  // unreachable: run every generation
    o.maxGenerations = quick ? 10 : 50;
    const int reps = quick ? 2 : 5;
    double best = 1e9;
    EvolveResult r;
    for (int i = 0; i < reps; ++i) {
      o.seed = uint64_t(i + 1);
      const double t0 = now();
      r = evolve(tiles, o);
      best = std::min(best, now() - t0);
    }
    const double gens = o.maxGenerations + 1;  // the initial population included
    const double evals = o.population + double(o.maxGenerations) * (o.population - o.elite);
    std::printf(
        "{\"bench\":\"evolve\",\"case\":\"generations\",\"threads\":%d,\"population\":%d,\"k\":%d,\"generation\":%d,"
        "\"cells\":%d,\"ga_generations\":%d,\"reps\":%d,\"best_s\":%.4f,\"generations_per_s\":%.1f,"
        "\"evaluations_per_s\":%.0f,\"final_best\":%.4f}\n",
        threads, o.population, o.ruleSide, o.generation, 81 * 81, o.maxGenerations, reps, best, gens / best, evals / best,
        r.history.back().best);
    std::fflush(stdout);
  }

  {  // Time to a converged p4 pattern.
    EvolveOptions o;
    o.population = 100;
    o.ruleSide = 3;
    o.generation = 4;
    o.p4 = true;
    std::vector<double> times;
    int converged = 0, generations = 0;
    for (int s = 0; s < seeds; ++s) {
      o.seed = uint64_t(s + 1);
      const double t0 = now();
      const EvolveResult r = evolve(tiles, o);
      const double t = now() - t0;
      times.push_back(t);
      converged += r.converged;
      generations += r.generations;
    }
    std::sort(times.begin(), times.end());
    std::printf(
        "{\"bench\":\"evolve\",\"case\":\"p4\",\"population\":%d,\"k\":%d,\"generation\":%d,\"threshold\":%.2f,"
        "\"seeds\":%d,\"converged\":%d,\"mean_ga_generations\":%.1f,\"median_s\":%.4f,\"max_s\":%.4f}\n",
        o.population, o.ruleSide, o.generation, o.threshold, seeds, converged, double(generations) / seeds,
        times[times.size() / 2], times.back());
  }

  {  // Ornament triangles per second on a torus.
    const auto torus = fgsg::rt::surface::torus(2, 0.8);
    EvolveOptions o;
    o.generation = 1;
    o.p4 = true;
    const AlleleGrid pattern = expand(evolve(tiles, o).best, o.generation);
    double t0 = now();
    const PolycubeMap map(torus, PolycubeOptions{0, 8});
    const double polycubeS = now() - t0;
    t0 = now();
    const OffsetSurface room = offsetSurface(torus);
    const double offsetS = now() - t0;
    const auto height = [&](const MappedPoint& p) {
      return heightAt(room, torus, fgsg::rt::surface::SurfacePoint{p.face, p.bary});
    };
    double best = 1e9;
    SurfaceOrnamentStats stats;
    for (int i = 0; i < (quick ? 1 : 3); ++i) {
      t0 = now();
      surfaceOrnament(tiles, pattern, map, height, {}, &stats);
      best = std::min(best, now() - t0);
    }
    std::printf(
        "{\"bench\":\"evolve\",\"case\":\"ornament\",\"surface\":\"torus(2, 0.8)\",\"faces\":%zu,\"facelets\":%zu,"
        "\"cells\":%zu,\"triangles\":%zu,\"polycube_s\":%.3f,\"offset_s\":%.3f,\"ornament_s\":%.3f,"
        "\"triangles_per_s\":%.0f}\n",
        torus.faceCount(), stats.facelets, stats.cells, stats.triangles, polycubeS, offsetS, best,
        double(stats.triangles) / best);
  }
  return 0;
}
