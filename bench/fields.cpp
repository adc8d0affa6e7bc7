// Field design and editing (FGSG §4.2), one core: on a torus of about 26 K vertices, the
// one-off preparation (the heat method's factorisations; none for the exponential map),
// designing a tensor field from four elements, 300 iterations of Laplacian smoothing (the
// paper's Fig. 7); tangent frames, finding the singularities, the curvature tensor. Prints
// one JSON object per line; the best of several repetitions is reported.
//   build/bin/bench_fields [--quick]
#include "runtime/field/curvature.h"
#include "runtime/field/design.h"
#include "runtime/field/singularities.h"
#include "runtime/field/smooth.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

namespace {

using namespace fgsg::rt;
using namespace fgsg::rt::field;

constexpr double kPi = 3.14159265358979323846;
constexpr int kSmoothIterations = 300;

// A torus around Z with nu x nv vertices, faces facing outward.
SurfaceMesh torus(int nu, int nv, double R, double r) {
  SurfaceMesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
      m.vertices.push_back({(R + r * std::cos(v)) * std::cos(u),
                            (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  auto id = [&](int i, int j) { return (i % nu) * nv + j % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      m.faces.push_back({a, b, c});
      m.faces.push_back({a, c, d});
    }
  m.buildTopology();
  return m;
}

double seconds(const std::function<void()>& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

SurfacePoint near(const SurfaceMesh& m, const Vec3& target) {
  SurfacePoint best;
  double bestDist = INFINITY;
  for (size_t f = 0; f < m.faceCount(); ++f) {
    SurfacePoint p;
    p.face = int(f);
    const double d = (p.position(m) - target).norm();
    if (d < bestDist) bestDist = d, best = p;
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int reps = quick ? 1 : 5;
  const SurfaceMesh mesh = torus(256, 102, 2.0, 0.8);

  double framesBest = 1e30, smoothBest = 1e30, singularBest = 1e30, curvatureBest = 1e30;
  for (auto method : {PolarMethod::Heat, PolarMethod::ExponentialMap}) {
    double prepareBest = 1e30, designBest = 1e30;
    size_t before = 0, after = 0;
    int indexSum = 0;
    for (int rep = 0; rep < reps; ++rep) {
      std::shared_ptr<const TangentFrames> frames;
      framesBest = std::min(framesBest, seconds([&] { frames = TangentFrames::make(mesh); }));
      std::unique_ptr<FieldDesigner> designer;
      prepareBest = std::min(prepareBest, seconds([&] {
        designer = std::make_unique<FieldDesigner>(frames, method);
      }));
      if (!designer->ok()) {
        std::fprintf(stderr, "%s\n", designer->heatGeodesics()->error().c_str());
        return 1;
      }
      std::vector<DesignElement> elements(4);
      elements[0].at = near(mesh, Vec3(2.8, 0, 0));
      elements[0].direction = Vec3(0, 1, 0);
      elements[1].kind = ElementKind::Wedge;
      elements[1].at = near(mesh, Vec3(-2.8, 0, 0));
      elements[2].kind = ElementKind::Trisector;
      elements[2].at = near(mesh, Vec3(0, 2, 0.8));
      elements[3].at = near(mesh, Vec3(0, -1.2, 0));
      elements[3].direction = Vec3(0, 0, 1);
      for (auto& e : elements) e.decay = 1.5;
      TangentField field(frames, FieldType::Tensor);
      std::string error;
      designBest = std::min(designBest, seconds([&] {
        if (!designer->design(FieldType::Tensor, elements, field, error)) {
          std::fprintf(stderr, "%s\n", error.c_str());
          std::exit(1);
        }
      }));
      before = field.degeneracies().size();
      smoothBest = std::min(smoothBest, seconds([&] { smooth(field, kSmoothIterations); }));
      singularBest = std::min(singularBest, seconds([&] {
        after = findDegeneracies(field).size();
      }));
      indexSum = indexSumTimesTwo(field.degeneracies());
      curvatureBest = std::min(curvatureBest, seconds([&] { curvatureTensor(frames); }));
    }
    std::printf("{\"bench\":\"field_design\",\"polar\":\"%s\",\"vertices\":%zu,"
                "\"faces\":%zu,\"elements\":4,\"prepare_s\":%.6f,\"design_s\":%.6f,"
                "\"smooth_s\":%.6f,\"iterations\":%d,\"design_and_smooth_s\":%.6f,"
                "\"with_prepare_s\":%.6f,\"singularities_before\":%zu,"
                "\"singularities_after\":%zu,\"index_sum_times_two\":%d}\n",
                method == PolarMethod::Heat ? "heat" : "exponential_map", mesh.vertexCount(),
                mesh.faceCount(), prepareBest, designBest, smoothBest, kSmoothIterations,
                designBest + smoothBest, prepareBest + designBest + smoothBest, before, after,
                indexSum);
    std::fflush(stdout);
  }
  std::printf("{\"bench\":\"field_queries\",\"vertices\":%zu,\"frames_s\":%.6f,"
              "\"singularities_s\":%.6f,\"curvature_s\":%.6f}\n",
              mesh.vertexCount(), framesBest, singularBest, curvatureBest);
  return 0;
}
