// Writing a large mesh, against the disk: a generated height field (an n x n vertex grid,
// 10^6 vertices and about 2 M triangles by default) with normals, colours and texture
// coordinates is written as .glb, .obj and .ply through writeMesh (encode, temporary file,
// fsync, rename: what `fgsg run -o` does); in the same run the identical bytes (read back
// from the written file) are written with plain write + fsync + rename. The ratio of the
// two is the writer's cost over the bytes' own; the goal is at most 1.5 for every format.
// Writer and raw runs alternate, so that a change in the machine's load hits both; the
// encoder alone (into a sink that keeps nothing) is timed too.
// Prints one JSON object per line; the best of several repetitions is reported.
//   build/bin/bench_write [--quick] [--side N] [--dir FOLDER]
#include "bench/bench_clock.h"
#include "runtime/io/write_mesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace {

using namespace fgsg;

using bench::cpuSeconds;
using bench::secondsSince;

// A gently curved height field: vertices row by row, two triangles per cell; the values
// look like an assembled model's (not round numbers, not random bit patterns).
rt::Mesh gridMesh(int side) {
  rt::Mesh m;
  const size_t n = size_t(side) * side;
  m.positions.resize(3 * n);
  m.colors.resize(3 * n);
  m.texcoords.resize(2 * n);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const size_t v = size_t(y) * side + x;
      const float u = float(x) / float(side - 1), w = float(y) / float(side - 1);
      const float h = 0.1f * std::sin(6 * u) * std::cos(5 * w);
      const float p[3] = {3.7f * u - 1.3f, h, 2.9f * w + 0.25f};
      const float c[3] = {0.2f + 0.6f * u, 0.5f + 4 * h, 0.9f - 0.7f * w};
      std::copy(p, p + 3, &m.positions[3 * v]);
      std::copy(c, c + 3, &m.colors[3 * v]);
      m.texcoords[2 * v] = 2 * u;
      m.texcoords[2 * v + 1] = 2 * w;
    }
  m.indices.resize(size_t(6) * (side - 1) * (side - 1));
  size_t i = 0;
  for (int y = 0; y + 1 < side; ++y)
    for (int x = 0; x + 1 < side; ++x) {
      const uint32_t a = uint32_t(y * side + x), b = a + 1, c = a + uint32_t(side), d = c + 1;
      for (uint32_t k : {a, b, d, a, d, c}) m.indices[i++] = k;
    }
  m.computeNormals();
  return m;
}

// Counts the bytes and keeps none: the encoder's own cost, without the file.
class NullSink final : public rt::io::ByteSink {
 protected:
  bool drain(const char*, size_t) override { return true; }
};

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The baseline: the bytes alone, written as writeMesh's output is (a new temporary beside
// the target, one write loop, fsync, close, rename).
double rawWrite(const std::string& path, const std::string& bytes) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string temp = path + ".raw.tmp";
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  bool ok = fd >= 0;
  for (size_t done = 0; ok && done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    ok = n > 0;
    done += ok ? size_t(n) : 0;
  }
  ok = ok && ::fsync(fd) == 0;
  ok = fd >= 0 && ::close(fd) == 0 && ok;
  ok = ok && ::rename(temp.c_str(), path.c_str()) == 0;
  if (!ok) {
    std::perror(temp.c_str());
    std::exit(1);
  }
  return secondsSince(t0);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int side = 1000;
  std::string dir = std::filesystem::temp_directory_path().string();
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) quick = true, side = 500;
    if (std::strcmp(argv[i], "--side") == 0 && i + 1 < argc) side = std::atoi(argv[++i]);
    if (std::strcmp(argv[i], "--dir") == 0 && i + 1 < argc) dir = argv[++i];
  }
  side = std::max(side, 2);
  const int reps = quick ? 2 : 5;
  const rt::Mesh mesh = gridMesh(side);
  const std::string stem = (std::filesystem::path(dir) / ("fgsg_bench_write_" + std::to_string(::getpid()))).string();

  for (const char* ext : {".glb", ".obj", ".ply"}) {
    const std::string target = stem + ext, rawTarget = stem + ".raw" + ext;
    double bestWriter = 1e30, bestWriterCpu = 1e30, bestRaw = 1e30, bestEncode = 1e30;
    std::string bytes;
    for (int r = 0; r < reps; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = cpuSeconds();
      std::string error;
      if (!rt::io::writeMesh(mesh, target, error)) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 1;
      }
      bestWriter = std::min(bestWriter, secondsSince(t0));
      bestWriterCpu = std::min(bestWriterCpu, cpuSeconds() - c0);
      if (bytes.empty()) bytes = readFile(target);
      bestRaw = std::min(bestRaw, rawWrite(rawTarget, bytes));
      const auto t1 = std::chrono::steady_clock::now();
      NullSink nothing;
      if (!rt::io::encodeMesh(mesh, ext, nothing, error)) return 1;
      bestEncode = std::min(bestEncode, secondsSince(t1));
    }
    std::filesystem::remove(target);
    std::filesystem::remove(rawTarget);
    std::printf("{\"bench\":\"write\",\"format\":\"%s\",\"triangles\":%zu,\"megabytes\":%.1f,"
                "\"writer_seconds\":%.3f,\"writer_cpu_seconds\":%.3f,\"encode_only_seconds\":%.3f,\"raw_seconds\":%.3f,"
                "\"ratio\":%.2f}\n",
                ext + 1, mesh.triangleCount(), double(bytes.size()) / (1 << 20), bestWriter, bestWriterCpu,
                bestEncode, bestRaw, bestWriter / bestRaw);
    std::fflush(stdout);
  }
  return 0;
}
