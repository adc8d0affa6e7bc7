// Generated atlases (buildAtlas) of the test meshes, charts flattened on all cores:
// charts, time (best of several runs, the surface already loaded) and coverage (the share
// of the unit square the charts cover). The goal: well under 0.5 s for a 100 K-triangle mesh.
// Also the time to load each mesh (once), and for a mesh with texture coordinates the time
// to validate and re-pack them (atlasFromTextureUV, once).
// Prints one JSON object per line.
//   build/bin/bench_atlas [--quick] [--deviation DEGREES] [MESH.off ...]
//   (default: tests/data/meshes' large ones, AtlasOptions' default deviation)
#include "runtime/atlas/atlas.h"
#include "runtime/surface/load_surface.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace fgsg::rt;
  int runs = 5;
  std::vector<std::string> paths;
  atlas::AtlasOptions options;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      runs = 1;
    else if (std::strcmp(argv[i], "--deviation") == 0 && i + 1 < argc)
      options.maxNormalDeviation = std::atof(argv[++i]);
    else
      paths.push_back(argv[i]);
  }
  if (paths.empty())
    for (const char* name : {"bunny00.off", "armadillo.off", "elephant.off", "ChineseDragon-10kv.off",
                             "refined_elephant.off"})
      paths.push_back(std::string(FGSG_SOURCE_DIR) + "/tests/data/meshes/" + name);
  for (const std::string& path : paths) {
    surface::SurfaceMesh mesh;
    std::string error;
    const auto loadStart = std::chrono::steady_clock::now();
    if (!surface::loadSurface(path, mesh, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    const double loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loadStart).count();
    // A mesh with its own texture coordinates: their validation and re-packing too.
    double textureSeconds = -1;
    if (!mesh.textureUV.empty()) {
      atlas::Atlas t;
      const auto start = std::chrono::steady_clock::now();
      if (!atlas::atlasFromTextureUV(mesh, options, t, error)) {
        std::fprintf(stderr, "%s: %s\n", path.c_str(), error.c_str());
        return 1;
      }
      textureSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    atlas::Atlas a;
    double best = 1e30;
    for (int r = 0; r < runs; ++r) {
      const auto start = std::chrono::steady_clock::now();
      if (!atlas::buildAtlas(mesh, options, a, error)) {
        std::fprintf(stderr, "%s: %s\n", path.c_str(), error.c_str());
        return 1;
      }
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    double covered = 0;
    for (const auto& t : a.cornerUV)
      covered += 0.5 * ((t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x());
    const std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("{\"mesh\": \"%s\", \"faces\": %zu, \"charts\": %d, \"seconds\": %.4f, \"coverage\": %.3f, "
                "\"load_seconds\": %.4f",
                name.c_str(), mesh.faces.size(), a.chartCount, best, covered, loadSeconds);
    if (textureSeconds >= 0) std::printf(", \"texture_atlas_seconds\": %.4f", textureSeconds);
    std::printf("}\n");
  }
  return 0;
}
