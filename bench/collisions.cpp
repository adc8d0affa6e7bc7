// Collision-tested instancing, one core: FGSG's Fig. 1 crack pattern (the paper: 521 K
// faces in 182 s with collision tests) derived with every instance tested, grown until
// its output is comparable; and the cost of one query against a populated world.
// Prints one JSON object per line; the best of several repetitions is reported.
//   build/bin/bench_collisions [--quick] [--depth N]
#include "backend/interp/interpreter.h"
#include "bench/bench_grammar.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "runtime/assemble.h"
#include "runtime/collision/collision_world.h"
#include "runtime/random.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace {

using namespace fgsg;
using Clock = std::chrono::steady_clock;

void crackPattern(int reps, uint32_t depth) {
  const ir::Module m = bench::compileGrammarFile(std::string(FGSG_SOURCE_DIR) +
                                                 "/examples/fig1_cracks_plane.fgsg");
  rt::DeriveOptions opt;
  opt.collideAll = true;
  opt.maxDepth = depth;
  opt.assetDirs = {std::string(FGSG_SOURCE_DIR) + "/examples/assets"};
  double best = 1e30;
  rt::DeriveResult kept;
  rt::AssetLibrary assets;
  assets.addSearchDir(opt.assetDirs[0]);
  for (int i = 0; i < reps; ++i) {
    rt::DeriveResult r = backend::interpret(m, opt, assets);
    if (!r.ok) {
      std::fprintf(stderr, "derivation failed: %s\n", r.messages.empty() ? "?" : r.messages[0].message.c_str());
      std::exit(1);
    }
    if (r.stats.deriveSeconds < best) best = r.stats.deriveSeconds, kept = std::move(r);
  }
  std::vector<int> meshOf;
  std::string error;
  if (!rt::resolveAssets(kept.instances, assets, meshOf, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    std::exit(1);
  }
  const auto& s = kept.stats;
  std::printf("{\"bench\":\"collisions\",\"grammar\":\"fig1_cracks_plane\",\"max_depth\":%u,"
              "\"instances\":%llu,\"faces\":%zu,\"collision_tests\":%llu,\"collisions\":%llu,"
              "\"seconds\":%.4f,\"us_per_test\":%.3f,\"faces_per_s\":%.0f}\n",
              depth, (unsigned long long)s.instances, rt::countTriangles(kept.instances, assets, meshOf),
              (unsigned long long)s.collisionTests, (unsigned long long)s.collisions, best,
              1e6 * best / std::max<uint64_t>(s.collisionTests, 1),
              rt::countTriangles(kept.instances, assets, meshOf) / best);
  std::fflush(stdout);
}

// Queries alone: random small cylinders against a world of `n` placed ones.
void queryCost(int reps, int n, int queries) {
  rt::AssetLibrary assets;
  std::string error;
  const int cylinder = assets.resolve("cylinder", error);
  auto randomBox = [](rt::RandomStream& rng, double extent) {
    rt::Scope s;
    s.P = rt::Vec3(rng.next() * extent, rng.next() * extent, 0);
    s.S = rt::Vec3(0.1, 0.55, 0.1);
    rt::rotateAboutNormal(s, rt::Vec3::UnitZ(), rng.next() * 360);
    return s.unitBoxToWorld();
  };
  const double extent = std::sqrt(n * 0.2);  // about one cylinder per 0.2 square units
  double best = 1e30;
  uint64_t hits = 0, narrow = 0;
  for (int r = 0; r < reps; ++r) {
    rt::CollisionWorld world(assets, rt::CollisionTest::Mesh, 0);
    rt::RandomStream rng{rt::rootKey(11), 0};
    for (int i = 0; i < n; ++i) world.add(cylinder, randomBox(rng, extent));
    std::vector<rt::Mat4> probes;
    for (int i = 0; i < queries; ++i) probes.push_back(randomBox(rng, extent));
    const uint64_t narrowBefore = world.narrowPhaseTests();
    hits = 0;
    const auto t0 = Clock::now();
    for (const auto& p : probes) hits += world.collides(cylinder, p);
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
    narrow = world.narrowPhaseTests() - narrowBefore;
  }
  std::printf("{\"bench\":\"collision_query\",\"obstacles\":%d,\"queries\":%d,\"hits\":%llu,"
              "\"narrow_tests\":%llu,\"us_per_query\":%.3f}\n",
              n, queries, (unsigned long long)hits, (unsigned long long)narrow, 1e6 * best / queries);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  uint32_t depth = 110;  // grows the pattern to about the paper's 521 K faces
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) quick = true, depth = 40;
    if (std::strcmp(argv[i], "--depth") == 0 && i + 1 < argc) depth = std::atoi(argv[++i]);
  }
  const int reps = quick ? 1 : 3;
  crackPattern(reps, depth);
  queryCost(reps, quick ? 2000 : 20000, quick ? 2000 : 20000);
  return 0;
}
