// CGA with real geometry (issue #16): examples/city.fgsg on the 200 lots of
// examples/city/lots.geojson — footprint polygons extruded, facades split into floors and
// windows, straight-skeleton roofs, every leaf output — derived and assembled into one
// mesh, on one thread. One JSON line per engine:
//   {"bench":"cga","engine":E,"lots":200,"instances":N,"triangles":T,"derive_s":..,
//    "assemble_s":..,"lots_per_s":..,"triangles_per_s":..}
// (best of `reps` runs; the JIT's compile excluded). The target: 10 000 lots per
// second on one core, with geometry.
// Usage: bench_cga [--quick]
#include "backend/interp/interpreter.h"
#include "backend/jit/jit.h"
#include "backend/native/object_cache.h"
#include "bench/bench_clock.h"
#include "bench/bench_grammar.h"
#include "runtime/assemble.h"
#include "runtime/io/geojson_lots.h"
#include "runtime/io/read_input.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>

using namespace fgsg;

namespace {

void run(const char* engine, size_t lots, int reps, const std::function<rt::DeriveResult()>& derive) {
  double bestDerive = 1e30, bestAssemble = 1e30;
  size_t instances = 0, triangles = 0;
  for (int i = 0; i < reps; ++i) {
    auto t0 = std::chrono::steady_clock::now();
    rt::DeriveResult r = derive();
    const double derived = bench::secondsSince(t0);
    if (!r.ok) {
      std::fprintf(stderr, "derivation failed: %s\n", r.messages.empty() ? "?" : r.messages[0].message.c_str());
      std::exit(1);
    }
    rt::AssetLibrary library;
    std::vector<int> meshOf;
    std::string error;
    t0 = std::chrono::steady_clock::now();
    if (!rt::resolveAssets(r.instances, library, meshOf, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      std::exit(1);
    }
    const rt::Mesh mesh = rt::assembleInstances(r.instances, library, meshOf);
    bestAssemble = std::min(bestAssemble, bench::secondsSince(t0));
    bestDerive = std::min(bestDerive, derived);
    instances = r.instances.instances.size();
    triangles = mesh.triangleCount();
  }
  const double total = bestDerive + bestAssemble;
  std::printf("{\"bench\":\"cga\",\"engine\":\"%s\",\"lots\":%zu,\"instances\":%zu,\"triangles\":%zu,"
              "\"derive_s\":%.6f,\"assemble_s\":%.6f,\"lots_per_s\":%.0f,\"triangles_per_s\":%.0f}\n",
              engine, lots, instances, triangles, bestDerive, bestAssemble, lots / total, triangles / total);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  rt::DeriveOptions options;
  size_t skipped = 0;
  std::string error;
  options.lotsName = FGSG_SOURCE_DIR "/examples/city/lots.geojson";
  options.assetDirs = {FGSG_SOURCE_DIR "/examples"};  // the city's textures
  if (!rt::readGeoJsonLots(options.lotsName, options.lots, skipped, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  const std::string path = FGSG_SOURCE_DIR "/examples/city.fgsg";
  const ir::Module m = bench::compileGrammarFile(path);
  std::string source;
  if (!rt::io::readInputFile(path, "grammar", source, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  rt::AssetLibrary assets;
  const int reps = quick ? 1 : 5;
  run("interp", options.lots.size(), reps, [&] { return backend::interpret(m, options, assets); });
  backend::jit::Jit jit;
  const auto code = jit.compileProgram(m, source, backend::native::ObjectCache(std::string()),
                                       backend::native::Tiering::Optimized);
  run("jit", options.lots.size(), reps, [&] { return backend::deriveCompiled(m, code.program(), options, assets); });
}
