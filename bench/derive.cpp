// Derivation throughput of the interpreter, one core: terminal shapes per second for a
// planar FGSG grammar and an L-system, and triangles assembled and encoded per second.
// Prints one JSON object per line; the best of several repetitions is reported.
//   build/bin/bench_derive [--quick]
#include "backend/interp/interpreter.h"
#include "bench/bench_grammar.h"
#include "bench/bench_grammars.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "runtime/assemble.h"
#include "runtime/io/write_mesh.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

namespace {

using namespace fgsg;
using namespace fgsg::bench;

ir::Module compile(const char* text) { return bench::compileGrammarText(text); }

struct Best {
  double seconds = 1e30;
  rt::DeriveResult result;
};

Best deriveBest(const ir::Module& m, int reps, rt::AssetLibrary& assets) {
  Best best;
  for (int i = 0; i < reps; ++i) {
    rt::DeriveResult r = backend::interpret(m, {}, assets);
    if (!r.ok) {
      std::fprintf(stderr, "derivation failed: %s\n", r.messages.empty() ? "?" : r.messages[0].message.c_str());
      std::exit(1);
    }
    if (r.stats.deriveSeconds < best.seconds) {
      best.seconds = r.stats.deriveSeconds;
      best.result = std::move(r);
    }
  }
  return best;
}

void reportDerive(const char* name, const Best& b) {
  const auto& s = b.result.stats;
  std::printf("{\"bench\":\"derive\",\"engine\":\"interp\",\"grammar\":\"%s\",\"shapes\":%llu,"
              "\"terminals\":%llu,\"instances\":%llu,\"seconds\":%.6f,\"shapes_per_s\":%.0f,"
              "\"terminals_per_s\":%.0f}\n",
              name, (unsigned long long)s.shapesCreated, (unsigned long long)s.terminals,
              (unsigned long long)s.instances, b.seconds, s.shapesCreated / b.seconds,
              s.terminals / b.seconds);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int reps = quick ? 1 : 5;
  rt::AssetLibrary assets;

  reportDerive("planar", deriveBest(compile(kPlanar), reps, assets));
  reportDerive("stochastic", deriveBest(compile(kStochastic), reps, assets));
  reportDerive("lsystem", deriveBest(compile(kLSystem), reps, assets));
  Best inst = deriveBest(compile(kPlanarInstances), reps, assets);
  reportDerive("planar_instances", inst);

  // Output: assemble the instances into one mesh and encode it as .glb in memory.
  std::vector<int> meshOf;
  std::string error;
  if (!rt::resolveAssets(inst.result.instances, assets, meshOf, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  double assembleBest = 1e30, encodeBest = 1e30;
  size_t triangles = 0, bytes = 0;
  for (int i = 0; i < (quick ? 1 : 3); ++i) {
    auto t0 = std::chrono::steady_clock::now();
    rt::Mesh mesh = rt::assembleInstances(inst.result.instances, assets, meshOf);
    auto t1 = std::chrono::steady_clock::now();
    std::string glb;
    if (!rt::io::encodeMesh(mesh, ".glb", glb, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    auto t2 = std::chrono::steady_clock::now();
    assembleBest = std::min(assembleBest, std::chrono::duration<double>(t1 - t0).count());
    encodeBest = std::min(encodeBest, std::chrono::duration<double>(t2 - t1).count());
    triangles = mesh.triangleCount();
    bytes = glb.size();
  }
  std::printf("{\"bench\":\"output\",\"format\":\"glb\",\"triangles\":%zu,\"bytes\":%zu,"
              "\"assemble_s\":%.6f,\"encode_s\":%.6f,\"triangles_per_s\":%.0f}\n",
              triangles, bytes, assembleBest, encodeBest, triangles / (assembleBest + encodeBest));
  return 0;
}
