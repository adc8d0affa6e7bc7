// Tracing on a surface (FGSG §4.3), one core: the cost of a triangle crossing for
// straightest geodesics and for streamlines of a vector and a line field, on meshes of
// about 26 K vertices: a bumpy torus, and the Stanford armadillo when
// tests/data/meshes holds it (scripts/fetch-test-meshes.sh); or a mesh given with --mesh.
// The field stores a tangent vector per vertex and blends the three of a face, as a
// designed field would. Prints one JSON object per line; the best of several repetitions
// is reported, timed in the thread's CPU time (the machines these run on are shared).
//   build/bin/bench_trace [--quick] [--mesh FILE]
#include "runtime/field/trace.h"
#include "runtime/surface/load_surface.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace fgsg::rt;
using namespace fgsg::rt::field;
using Clock = std::chrono::steady_clock;

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

constexpr double kPi = 3.14159265358979323846;

// A torus (radii 2 and 0.7) with bumps: nu x nv vertices.
SurfaceMesh bumpyTorus(int nu, int nv) {
  SurfaceMesh m;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
      const double r = 0.7 * (1 + 0.15 * std::sin(5 * u) * std::cos(3 * v));
      m.vertices.push_back(Vec3((2 + r * std::cos(v)) * std::cos(u),
                                (2 + r * std::cos(v)) * std::sin(u), r * std::sin(v)));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = j * nu + i, b = j * nu + (i + 1) % nu, c = ((j + 1) % nv) * nu + (i + 1) % nu,
                d = ((j + 1) % nv) * nu + i;
      m.faces.push_back({a, b, c});
      m.faces.push_back({a, c, d});
    }
  m.buildTopology();
  return m;
}

// A smooth field stored per vertex (a swirl about Z plus waves), blended linearly in a
// face and made a unit tangent at the point.
class VertexField : public DirectionField {
 public:
  VertexField(const SurfaceMesh& m, bool line) : m_(m), line_(line) {
    const Vec3 c = 0.5 * (m.boundsMin + m.boundsMax);
    const double size = (m.boundsMax - m.boundsMin).norm();
    for (size_t v = 0; v < m.vertices.size(); ++v) {
      const Vec3 y = (m.vertices[v] - c) / size;
      Vec3 f = Vec3(-y.y(), y.x(), 0.3 * y.x()) +
               0.4 * Vec3(std::sin(7 * y.y()), std::cos(5 * y.z()), std::sin(6 * y.x()));
      const Vec3& n = m.vertexNormals[v];
      values_.push_back(f - f.dot(n) * n);
    }
  }
  bool direction(const SurfacePoint& p, Vec3& out) const override {
    const auto& t = m_.faces[p.face];
    Vec3 f = p.bary[0] * values_[t[0]] + p.bary[1] * values_[t[1]] + p.bary[2] * values_[t[2]];
    const Vec3 n = p.normal(m_);
    f -= f.dot(n) * n;
    const double len = f.norm();
    if (!(len > 1e-12)) return false;
    out = f / len;
    return true;
  }
  bool isLineField() const override { return line_; }
  const std::vector<Degeneracy>& degeneraciesIn(int) const override { return none_; }

 private:
  const SurfaceMesh& m_;
  bool line_;
  std::vector<Vec3> values_;
  std::vector<Degeneracy> none_;
};

struct Job {
  SurfacePoint start;
  Vec3 dir;
  double angle, length;
};

std::vector<Job> jobs(const SurfaceMesh& m, int count) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g;
  const double size = (m.boundsMax - m.boundsMin).norm();
  std::vector<Job> out;
  for (int i = 0; i < count; ++i) {
    Job j;
    j.start.face = std::uniform_int_distribution<int>(0, int(m.faces.size()) - 1)(rng);
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    j.start.bary = Vec3(a, b, 1 - a - b);
    const Vec3 n = j.start.normal(m);
    Vec3 d(g(rng), g(rng), g(rng));
    j.dir = (d - d.dot(n) * n).normalized();
    j.angle = (u(rng) - 0.5) * 2 * kPi;
    j.length = size * (0.5 + u(rng));
    out.push_back(j);
  }
  return out;
}

// Runs every job `reps` times; reports the best repetition.
template <class Trace>
void run(const char* mesh, const char* kind, const SurfaceMesh& m, const std::vector<Job>& js,
         int reps, Trace trace) {
  double best = 1e30, bestWall = 1e30;
  long crossings = 0, stopped = 0;
  double length = 0;
  for (int r = 0; r < reps; ++r) {
    crossings = stopped = 0;
    length = 0;
    const auto t0 = Clock::now();
    const double c0 = cpuSeconds();
    for (const Job& j : js) {
      const TraceResult res = trace(j);
      crossings += res.crossings;
      stopped += res.stopped;
      length += res.length;
    }
    best = std::min(best, cpuSeconds() - c0);
    bestWall = std::min(bestWall, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  std::printf(
      "{\"bench\":\"trace\",\"mesh\":\"%s\",\"kind\":\"%s\",\"vertices\":%zu,\"faces\":%zu,"
      "\"traces\":%zu,\"stopped\":%ld,\"crossings\":%ld,\"mean_edges_per_trace\":%.1f,"
      "\"cpu_s\":%.4f,\"wall_s\":%.4f,\"ns_per_crossing\":%.1f,\"us_per_trace\":%.2f}\n",
      mesh, kind, m.vertices.size(), m.faces.size(), js.size(), stopped, crossings,
      length / js.size() / m.meanEdgeLength, best, bestWall, 1e9 * best / std::max(1L, crossings),
      1e6 * best / js.size());
  std::fflush(stdout);
}

// Geodesics, a vector field's and a line field's streamlines on one mesh.
void benchMesh(const char* name, const SurfaceMesh& m, bool quick) {
  const int reps = quick ? 1 : 5;
  const std::vector<Job> js = jobs(m, quick ? 200 : 2000);
  const VertexField vectors(m, false), lines(m, true);
  run(name, "geodesic", m, js, reps,
      [&](const Job& j) { return traceGeodesic(m, j.start, j.dir, j.length); });
  run(name, "vector_field", m, js, reps,
      [&](const Job& j) { return traceField(m, vectors, j.start, j.dir, j.angle, j.length); });
  run(name, "line_field", m, js, reps,
      [&](const Job& j) { return traceField(m, lines, j.start, j.dir, j.angle, j.length); });
}

bool load(const std::string& path, SurfaceMesh& m) {
  std::string error;
  if (surface::loadSurface(path, m, error)) return true;
  std::fprintf(stderr, "%s\n", error.c_str());
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string meshPath;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else if (std::strcmp(argv[i], "--mesh") == 0 && i + 1 < argc)
      meshPath = argv[++i];
  }
  SurfaceMesh m;
  if (!meshPath.empty()) {
    if (!load(meshPath, m)) return 1;
    benchMesh(std::filesystem::path(meshPath).filename().c_str(), m, quick);
    return 0;
  }
  benchMesh("bumpy_torus", bumpyTorus(200, 130), quick);
  const std::string armadillo = std::string(FGSG_SOURCE_DIR) + "/tests/data/meshes/armadillo.off";
  if (std::filesystem::exists(armadillo) && load(armadillo, m)) benchMesh("armadillo", m, quick);
  return 0;
}
