// On-mesh marching (Buron et al. 2015): building the 1024^2 indirection geometry image
// from a ready atlas (wall time, all cores: the build is parallel), reading it back from
// the disk cache, and march throughput (one core, thread CPU time; and all cores) for
// 10-texel steps in image and surface length. Meshes: a cube of 99 372 triangles with six
// hand-laid charts, and the bunny and the armadillo (tests/data/meshes) over the tests'
// box-projection atlases (hundreds of charts). Prints one JSON object per line; the best
// of several repetitions is reported (the machines these run on are shared).
//   build/bin/bench_marching [--quick]
#include "runtime/marching/geometry_image.h"
#include "runtime/marching/image_cache.h"
#include "runtime/marching/marching_surface.h"
#include "runtime/surface/load_surface.h"
#include "tests/unit/marching/box_projection_atlas.h"
#include "tests/unit/marching/charted_shapes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace fgsg::rt;
using namespace fgsg::rt::marching;
using namespace fgsg::rt::marching::testing;
using Clock = std::chrono::steady_clock;

double wallSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// Random starts: uniform faces, points and tangent directions.
std::vector<MarchPoint> starts(const MarchingSurface& s, int count) {
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<int> face(0, int(s.mesh().faceCount()) - 1);
  std::uniform_real_distribution<double> unit01(0, 1);
  std::vector<MarchPoint> out;
  for (int k = 0; k < count; ++k) {
    const int f = face(rng);
    double a = unit01(rng), b = unit01(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const Vec3 n = s.mesh().faceNormals[f], e = n.unitOrthogonal(), e2 = n.cross(e);
    const double phi = 6.283185307179586 * unit01(rng);
    out.push_back(s.place({f, Vec3(1 - a - b, a, b)}, std::cos(phi) * e + std::sin(phi) * e2));
  }
  return out;
}

void bench(const char* name, const ChartedMesh& c, bool quick) {
  const int reps = quick ? 1 : 5;
  std::string error;
  std::shared_ptr<const MarchingSurface> s;
  double build = 1e9;
  ImageStats phases;
  for (int r = 0; r < reps; ++r) {
    const auto t = Clock::now();
    s = MarchingSurface::fromAtlas(c.mesh, c.atlas, MarchingOptions{}, error);
    const double seconds = wallSince(t);
    if (!s) {
      std::fprintf(stderr, "%s: %s\n", name, error.c_str());
      return;
    }
    if (seconds < build) build = seconds, phases = s->image().stats();
  }
  // The cache: written once, read back (validated) best of reps.
  const auto dir = std::filesystem::temp_directory_path() / "fgsg-bench-marching";
  const std::string key = imageCacheKey(c.mesh, MarchingOptions{});
  const std::string path = imageCachePath(dir.string(), key);
  double read = 1e9;
  size_t bytes = 0;
  if (writeImageCache(path, key, *s, error)) {
    bytes = std::filesystem::file_size(path);
    for (int r = 0; r < reps; ++r) {
      const auto t = Clock::now();
      std::string why;
      if (!readImageCache(path, key, c.mesh, MarchingOptions{}, why)) std::fprintf(stderr, "%s: %s\n", name, why.c_str());
      read = std::min(read, wallSince(t));
    }
    std::filesystem::remove(path);
  }
  std::printf("{\"bench\":\"marching_image\",\"mesh\":\"%s\",\"faces\":%zu,\"charts\":%d,\"resolution\":%d,"
              "\"build_s\":%.4f,\"raster_s\":%.4f,\"points_s\":%.4f,\"pointers_s\":%.4f,\"levels_s\":%.4f,"
              "\"inner_texels\":%zu,\"indirection_texels\":%zu,\"pointers\":%zu,\"cache_bytes\":%zu,"
              "\"cache_read_s\":%.4f}\n",
              name, c.mesh.faceCount(), c.atlas.chartCount, c.atlas.resolution, build, phases.rasterSeconds,
              phases.pointSeconds, phases.pointerSeconds, phases.levelSeconds, phases.innerTexels,
              phases.indirectionTexels, phases.pointers, bytes, read);
  std::fflush(stdout);

  // Marches of 10 texels, and of the surface length 10 texels span on average.
  const std::vector<MarchPoint> from = starts(*s, quick ? 20000 : 200000);
  double texel = 0, area = 0;
  for (size_t f = 0; f < c.mesh.faceCount(); ++f) area += c.mesh.faceAreas[f];
  texel = std::sqrt(area / double(s->image().stats().innerTexels));
  for (LengthUnit unit : {LengthUnit::Image, LengthUnit::Surface}) {
    const double length = unit == LengthUnit::Image ? 10 : 10 * texel;
    double single = 1e9;
    long jumps = 0, pieces = 0, arrived = 0;
    for (int r = 0; r < reps; ++r) {
      jumps = pieces = arrived = 0;
      const double t = cpuSeconds();
      for (const MarchPoint& p : from) {
        MarchPoint to;
        MarchTrace trace;
        arrived += s->march(p, length, unit, to, &trace);
        jumps += trace.pointerJumps + trace.adjacencyJumps;
        pieces += trace.pieces;
      }
      single = std::min(single, cpuSeconds() - t);
    }
    double parallel = 1e9;
    for (int r = 0; r < reps; ++r) {
      const auto t = Clock::now();
      tbb::parallel_for(size_t(0), from.size(), [&](size_t i) {
        MarchPoint to;
        s->march(from[i], length, unit, to);
      });
      parallel = std::min(parallel, wallSince(t));
    }
    std::printf("{\"bench\":\"marching_march\",\"mesh\":\"%s\",\"unit\":\"%s\",\"length\":%.6g,\"marches\":%zu,"
                "\"arrived\":%ld,\"jumps_per_march\":%.3f,\"faces_per_march\":%.2f,\"one_core_per_s\":%.0f,"
                "\"all_cores_per_s\":%.0f,\"cores\":%d}\n",
                name, unit == LengthUnit::Image ? "image" : "surface", length, from.size(), arrived,
                double(jumps) / from.size(), double(pieces) / from.size(), from.size() / single,
                from.size() / parallel, tbb::this_task_arena::max_concurrency());
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else {
      std::fprintf(stderr, "usage: bench_marching [--quick]\n");
      return 2;
    }
  }
  bench("cube_99k", chartedCube(91, 1024), quick);
  const auto meshes = std::filesystem::path(FGSG_SOURCE_DIR) / "tests" / "data" / "meshes";
  for (const char* file : {"bunny00.off", "armadillo.off"}) {
    surface::SurfaceMesh mesh;
    std::string error;
    if (!surface::loadSurface((meshes / file).string(), mesh, error)) {
      std::fprintf(stderr, "skipping %s: %s\n", file, error.c_str());
      continue;
    }
    ChartedMesh c{mesh, boxProjectionAtlas(mesh, 1024)};
    bench(file, c, quick);
  }
}
