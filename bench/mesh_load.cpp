// Loading a large surface mesh, one core: an n x n vertex grid (10^6 vertices and about
// 2 M triangles by default, a gently curved height field) written as text OFF, then read,
// validated and given its topology by loadSurface, as `fgsg run --surface` does. The time
// is split into reading the file (parse and checks) and the whole load, each as wall-clock
// and as processor time. The goal: a
// 2 M-triangle mesh loads in under 2 s.
// Prints one JSON object per line; the best of several repetitions is reported.
//   build/bin/bench_mesh_load [--quick] [--side N]
#include "bench/bench_clock.h"
#include "runtime/io/read_mesh_file.h"
#include "runtime/surface/load_surface.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string>

namespace {

using namespace fgsg;

using bench::cpuSeconds;
using bench::secondsSince;

// The grid as text OFF: vertices row by row, two counter-clockwise triangles per cell.
void writeGridOff(const std::string& path, int side) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) {
    std::perror(path.c_str());
    std::exit(1);
  }
  const long cells = long(side - 1) * (side - 1);
  std::fprintf(f, "OFF\n%ld %ld 0\n", long(side) * side, 2 * cells);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const double u = double(x) / (side - 1), v = double(y) / (side - 1);
      std::fprintf(f, "%.9g %.9g %.9g\n", u, v, 0.1 * std::sin(6 * u) * std::cos(5 * v));
    }
  for (int y = 0; y + 1 < side; ++y)
    for (int x = 0; x + 1 < side; ++x) {
      const long a = long(y) * side + x, b = a + 1, c = a + side, d = c + 1;
      std::fprintf(f, "3 %ld %ld %ld\n3 %ld %ld %ld\n", a, b, d, a, d, c);
    }
  std::fclose(f);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int side = 1000;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    if (std::strcmp(argv[i], "--side") == 0 && i + 1 < argc) side = std::atoi(argv[++i]);
  }
  if (side < 2) side = 2;
  const int reps = quick ? 1 : 3;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("fgsg_bench_grid_" + std::to_string(side) + ".off"))
          .string();
  writeGridOff(path, side);
  const double megabytes = double(std::filesystem::file_size(path)) / (1 << 20);

  double bestRead = 1e30, bestLoad = 1e30, bestReadCpu = 1e30, bestLoadCpu = 1e30;
  size_t vertices = 0, faces = 0;
  for (int r = 0; r < reps; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    double c0 = cpuSeconds();
    rt::io::MeshFileContent content;
    std::string error;
    if (!rt::io::readMeshFile(path, content, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    bestRead = std::min(bestRead, secondsSince(t0));
    bestReadCpu = std::min(bestReadCpu, cpuSeconds() - c0);

    t0 = std::chrono::steady_clock::now();
    c0 = cpuSeconds();
    rt::surface::SurfaceMesh mesh;
    if (!rt::surface::loadSurface(path, mesh, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    bestLoad = std::min(bestLoad, secondsSince(t0));
    bestLoadCpu = std::min(bestLoadCpu, cpuSeconds() - c0);
    vertices = mesh.vertexCount();
    faces = mesh.faceCount();
  }
  std::filesystem::remove(path);
  std::printf("{\"bench\":\"mesh_load\",\"format\":\"off\",\"vertices\":%zu,\"faces\":%zu,"
              "\"megabytes\":%.1f,\"read_seconds\":%.3f,\"load_seconds\":%.3f,\"read_cpu_seconds\":%.3f,"
              "\"load_cpu_seconds\":%.3f}\n",
              vertices, faces, megabytes, bestRead, bestLoad, bestReadCpu, bestLoadCpu);
  return 0;
}
