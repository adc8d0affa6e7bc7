// Grammars on surfaces, one core: output faces per second for the FGSG examples that grow
// on a surface (the paper's Table 1 is the anchor: 568 K faces in 0.5 s, 1.2 M in 10 s).
// Faces are the triangles of the placed instances (the surface itself left out); the
// time is the derivation's, surface and fields built included.
// Prints one JSON object per line; the best of several repetitions is reported.
//   build/bin/bench_surfaces [--quick]
#include "backend/interp/interpreter.h"
#include "bench/bench_grammar.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "runtime/assemble.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

namespace {

using namespace fgsg;

void example(const char* name, int reps) {
  const std::string dir = std::string(FGSG_SOURCE_DIR) + "/examples";
  const ir::Module m = bench::compileGrammarFile(dir + "/" + name + ".fgsg");
  rt::DeriveOptions opt;
  opt.assetDirs = {dir, dir + "/assets"};
  double best = 1e30;
  size_t faces = 0, instances = 0;
  for (int i = 0; i < reps; ++i) {
    rt::AssetLibrary assets;
    for (const auto& d : opt.assetDirs) assets.addSearchDir(d);
    rt::DeriveResult r = backend::interpret(m, opt, assets);
    if (!r.ok) {
      std::fprintf(stderr, "%s: %s\n", name, r.messages.empty() ? "?" : r.messages[0].message.c_str());
      std::exit(1);
    }
    if (r.stats.deriveSeconds >= best) continue;
    best = r.stats.deriveSeconds;
    r.instances.instances.pop_back();  // the surface's own mesh
    std::vector<int> meshOf;
    std::string error;
    if (!rt::resolveAssets(r.instances, assets, meshOf, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      std::exit(1);
    }
    faces = rt::countTriangles(r.instances, assets, meshOf);
    instances = r.instances.instances.size();
  }
  std::printf("{\"bench\":\"surface\",\"example\":\"%s\",\"instances\":%zu,\"faces\":%zu,"
              "\"seconds\":%.4f,\"faces_per_s\":%.0f}\n",
              name, instances, faces, best, faces / best);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int reps = quick ? 1 : 3;
  for (const char* name : {"stem_leaf", "fig4_on_surface", "curvature_glyphs", "fig12_mosaic"})
    example(name, reps);
  return 0;
}
