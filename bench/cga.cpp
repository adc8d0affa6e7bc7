// CGA with real geometry (issue #16): examples/city.fgsg on the 200 lots of
// examples/city/lots.geojson — footprint polygons extruded, facades split into floors and
// windows, straight-skeleton roofs, every leaf output — derived and assembled into one
// mesh, on one thread. One JSON line per engine:
//   {"bench":"cga","engine":E,"lots":200,"instances":N,"triangles":T,"derive_s":..,
//    "assemble_s":..,"lots_per_s":..,"triangles_per_s":..}
// (best of `reps` runs; the JIT's compile excluded). The target: 10 000 lots per
// second on one core, with geometry.
//
// --pair [A.cga B.fgsg]: a CityEngine rule file and the same grammar in the fgsg dialect
// (default bench/cga_pair/building.cga and building.fgsg), each on the same 200 lots, one
// line per grammar and engine, then per engine
//   {"bench":"cga_pair","engine":E,"cga_lots_per_s":..,"fgsg_lots_per_s":..,"ratio":..}
// (ratio: the .cga file's speed over the .fgsg file's; issue #43's target is 1).
//
// --scene: the structured output (#45) instead of the one assembled mesh, JIT only: per
// run the derivation, the scene (runtime/output/: a node per lot, grouped by symbol,
// --instancing auto, as fgsg run -o FILE.glb), its .glb encoded, and for comparison the
// flattened mesh assembled; then one line
//   {"bench":"cga_scene","lots":200,"derive_s":..,"scene_s":..,"encode_s":..,"flatten_s":..,
//    "derive_cpu_s":.., ..., "lots_per_s":..,"cpu_lots_per_s":..,"cpu_lots_per_s_written":..,
//    "cpu_lots_per_s_flattened":..,"glb_auto_bytes":..,"glb_on_bytes":..,"glb_flat_bytes":..,
//    "auto_over_flat":..,"on_over_flat":..}
// (lots_per_s: derived and assembled into the scene, by the wall clock; cpu_: by processor
// time; _written: the .glb encoded too; _flattened: derived and assembled into one mesh;
// the flattened .glb is `--instancing off --group-by none`'s).
// --earclip: the flat roof of a comb-shaped lot (2 002 corners, 500 teeth; issue #42's took
// most of a minute) ear-clipped, best of `reps`: {"bench":"cga_earclip","corners":2002,
// "triangles":2000,"seconds":..} (before #42's fix: tens of seconds; since: milliseconds).
// Usage: bench_cga [--quick] [--pair [A.cga B.fgsg]] [--scene] [--earclip]
#include "backend/interp/interpreter.h"
#include "backend/jit/jit.h"
#include "backend/native/object_cache.h"
#include "bench/bench_clock.h"
#include "bench/bench_grammar.h"
#include "backend/scene_starts.h"
#include "runtime/assemble.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/io/write_mesh.h"
#include "runtime/output/gltf_writer.h"
#include "runtime/output/scene.h"
#include "runtime/io/geojson_lots.h"
#include "runtime/io/read_input.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace fgsg;

namespace {

// Returns lots per second (derive and assemble).
double run(const char* engine, size_t lots, int reps, const std::function<rt::DeriveResult()>& derive,
           const std::string& grammar = "") {
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
  const std::string named = grammar.empty() ? "" : ",\"grammar\":\"" + grammar + "\"";
  std::printf("{\"bench\":\"cga\"%s,\"engine\":\"%s\",\"lots\":%zu,\"instances\":%zu,\"triangles\":%zu,"
              "\"derive_s\":%.6f,\"assemble_s\":%.6f,\"lots_per_s\":%.0f,\"triangles_per_s\":%.0f}\n",
              named.c_str(), engine, lots, instances, triangles, bestDerive, bestAssemble, lots / total,
              triangles / total);
  std::fflush(stdout);
  return lots / total;
}

std::string readSource(const std::string& path) {
  std::string source, error;
  if (!rt::io::readInputFile(path, "grammar", source, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    std::exit(1);
  }
  return source;
}

// The two dialects side by side: lots/s of each grammar with each engine, and their ratio.
void runPair(const std::string& cgaPath, const std::string& fgsgPath, const rt::DeriveOptions& options, int reps) {
  rt::AssetLibrary assets;
  const std::string paths[2] = {cgaPath, fgsgPath};
  double speed[2][2] = {};  // [grammar][interp, jit]
  backend::jit::Jit jit;
  for (int g = 0; g < 2; ++g) {
    const ir::Module m = bench::compileGrammarFile(paths[g]);
    const std::string source = readSource(paths[g]);
    speed[g][0] = run("interp", options.lots.size(), reps, [&] { return backend::interpret(m, options, assets); },
                      paths[g]);
    const auto code = jit.compileProgram(m, source, backend::native::ObjectCache(std::string()),
                                         backend::native::Tiering::Optimized);
    speed[g][1] = run("jit", options.lots.size(), reps,
                      [&] { return backend::deriveCompiled(m, code.program(), options, assets); }, paths[g]);
  }
  for (int e = 0; e < 2; ++e)
    std::printf("{\"bench\":\"cga_pair\",\"engine\":\"%s\",\"cga_lots_per_s\":%.0f,\"fgsg_lots_per_s\":%.0f,"
                "\"ratio\":%.3f}\n",
                e == 0 ? "interp" : "jit", speed[0][e], speed[1][e], speed[0][e] / speed[1][e]);
}

// The structured output's speed and size (--scene). Each phase is timed by the wall
// clock and by the process's processor time (which another process on a shared machine
// does not inflate); the best of `reps` runs of each.
void runScene(const ir::Module& m, const std::function<rt::DeriveResult()>& derive, const rt::DeriveOptions& options,
              int reps) {
  struct Best {
    double wall = 1e30, cpu = 1e30;
  } derived, scened, encoded, flattened;
  size_t autoBytes = 0, onBytes = 0, flatBytes = 0, quantizedBytes = 0;
  const auto fail = [](const std::string& error) {
    std::fprintf(stderr, "%s\n", error.c_str());
    std::exit(1);
  };
  // Runs `f`, keeping its best wall and processor times in `best`.
  const auto timed = [](Best& best, const auto& f) {
    const double cpu0 = bench::cpuSeconds();
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best.wall = std::min(best.wall, bench::secondsSince(t0));
    best.cpu = std::min(best.cpu, bench::cpuSeconds() - cpu0);
  };
  for (int i = 0; i < reps; ++i) {
    rt::DeriveResult r;
    timed(derived, [&] { r = derive(); });
    if (!r.ok) fail("derivation failed: " + (r.messages.empty() ? std::string("?") : r.messages[0].message));
    rt::AssetLibrary library;
    for (const std::string& dir : options.assetDirs) library.addSearchDir(dir);
    std::vector<int> meshOf;
    std::string error;
    if (!rt::resolveAssets(r.instances, library, meshOf, error)) fail(error);
    rt::output::SceneInput in;
    in.list = &r.instances;
    in.library = &library;
    in.meshOf = &meshOf;
    in.groupBy = rt::output::GroupBy::Symbol;
    in.instancing = rt::output::Instancing::Auto;
    rt::output::Scene scene;
    timed(scened, [&] {
      in.starts = backend::sceneStarts(m, options, r);
      scene = rt::output::buildScene(in);
    });
    std::string bytes;
    timed(encoded, [&] {
      if (!rt::output::encodeGltf(scene, true, bytes, error)) fail(error);
    });
    autoBytes = bytes.size();
    rt::Mesh mesh;
    timed(flattened, [&] { mesh = rt::assembleInstances(r.instances, library, meshOf); });
    if (i > 0) continue;
    // The sizes, once: the flattened file, and every rigid repeat instanced.
    if (!rt::io::encodeMesh(mesh, ".glb", bytes, error)) fail(error);
    flatBytes = bytes.size();
    if (!rt::output::encodeGltf(scene, true, bytes, error, nullptr, {.quantize = true})) fail(error);
    quantizedBytes = bytes.size();
    in.instancing = rt::output::Instancing::On;
    if (!rt::output::encodeGltf(rt::output::buildScene(in), true, bytes, error)) fail(error);
    onBytes = bytes.size();
  }
  const double lots = double(options.lots.size());
  std::printf("{\"bench\":\"cga_scene\",\"lots\":%zu,\"derive_s\":%.6f,\"scene_s\":%.6f,\"encode_s\":%.6f,"
              "\"flatten_s\":%.6f,\"derive_cpu_s\":%.6f,\"scene_cpu_s\":%.6f,\"encode_cpu_s\":%.6f,"
              "\"flatten_cpu_s\":%.6f,\"lots_per_s\":%.0f,\"cpu_lots_per_s\":%.0f,\"cpu_lots_per_s_written\":%.0f,"
              "\"cpu_lots_per_s_flattened\":%.0f,\"glb_auto_bytes\":%zu,\"glb_on_bytes\":%zu,\"glb_flat_bytes\":%zu,"
              "\"glb_quantized_bytes\":%zu,\"auto_over_flat\":%.3f,\"quantized_over_flat\":%.3f,\"on_over_flat\":%.3f}\n",
              options.lots.size(), derived.wall, scened.wall, encoded.wall, flattened.wall, derived.cpu, scened.cpu,
              encoded.cpu, flattened.cpu, lots / (derived.wall + scened.wall), lots / (derived.cpu + scened.cpu),
              lots / (derived.cpu + scened.cpu + encoded.cpu), lots / (derived.cpu + flattened.cpu), autoBytes, onBytes,
              flatBytes, quantizedBytes, double(autoBytes) / double(flatBytes), double(quantizedBytes) / double(flatBytes),
              double(onBytes) / double(flatBytes));
  std::fflush(stdout);
}

}  // namespace

void runCombEarClip(int reps) {
  rt::cga::Polygon3 comb = {rt::Vec3(0, 0, 0), rt::Vec3(1000, 0, 0)};
  const int h = 1000;
  for (int y = 1; y < h; ++y) {
    if (y % 2) comb.insert(comb.end(), {rt::Vec3(1000, y, 0), rt::Vec3(1, y, 0)});
    else comb.insert(comb.end(), {rt::Vec3(1, y, 0), rt::Vec3(1000, y, 0)});
  }
  comb.insert(comb.end(), {rt::Vec3(1, h, 0), rt::Vec3(0, h, 0)});
  double best = 1e300;
  std::vector<uint32_t> tris;
  for (int r = 0; r < reps; ++r) {
    const auto start = std::chrono::steady_clock::now();
    tris.clear();
    rt::cga::earClip(comb, tris);
    best = std::min(best, bench::secondsSince(start));
  }
  std::printf("{\"bench\":\"cga_earclip\",\"corners\":%zu,\"triangles\":%zu,\"seconds\":%.6f}\n", comb.size(),
              tris.size() / 3, best);
}

int main(int argc, char** argv) {
  bool quick = false, pair = false, sceneOnly = false, earClipOnly = false;
  std::vector<std::string> pairFiles;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    else if (std::strcmp(argv[i], "--pair") == 0) pair = true;
    else if (std::strcmp(argv[i], "--scene") == 0) sceneOnly = true;
    else if (std::strcmp(argv[i], "--earclip") == 0) earClipOnly = true;
    else if (pair) pairFiles.push_back(argv[i]);
    else {
      std::fprintf(stderr, "usage: bench_cga [--quick] [--pair [A.cga B.fgsg]] [--scene] [--earclip]\n");
      return 2;
    }
  }
  if (pair && pairFiles.size() != 0 && pairFiles.size() != 2) {
    std::fprintf(stderr, "bench_cga --pair takes a .cga file and its .fgsg twin, or neither\n");
    return 2;
  }
  tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  if (earClipOnly) {
    runCombEarClip(quick ? 1 : 5);
    return 0;
  }
  rt::DeriveOptions options;
  size_t skipped = 0;
  std::string error;
  options.lotsName = FGSG_SOURCE_DIR "/examples/city/lots.geojson";
  options.assetDirs = {FGSG_SOURCE_DIR "/examples"};  // the city's textures
  if (!rt::readGeoJsonLots(options.lotsName, options.lots, skipped, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  if (pair) {
    if (pairFiles.empty())
      pairFiles = {FGSG_SOURCE_DIR "/bench/cga_pair/building.cga", FGSG_SOURCE_DIR "/bench/cga_pair/building.fgsg"};
    runPair(pairFiles[0], pairFiles[1], options, quick ? 1 : 5);
    return 0;
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
  if (sceneOnly) {
    backend::jit::Jit jit;
    const auto code = jit.compileProgram(m, source, backend::native::ObjectCache(std::string()),
                                         backend::native::Tiering::Optimized);
    runScene(m, [&] { return backend::deriveCompiled(m, code.program(), options, assets); }, options, reps);
    return 0;
  }
  run("interp", options.lots.size(), reps, [&] { return backend::interpret(m, options, assets); });
  backend::jit::Jit jit;
  const auto code = jit.compileProgram(m, source, backend::native::ObjectCache(std::string()),
                                       backend::native::Tiering::Optimized);
  run("jit", options.lots.size(), reps, [&] { return backend::deriveCompiled(m, code.program(), options, assets); });
}
