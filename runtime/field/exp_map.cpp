#include "runtime/field/exp_map.h"

#include "runtime/field/complex_direction.h"

#include <algorithm>
#include <queue>

namespace fgsg::rt::field {

namespace {

using Complex = std::complex<double>;

}  // namespace

PolarMap exponentialMap(const TangentFrames& F, const SurfacePoint& source,
                        const Vec3& reference, double maxDistance) {
  const SurfaceMesh& mesh = F.mesh();
  const int nv = int(mesh.vertexCount());
  const int sf = source.face;
  std::vector<Complex> U(nv, Complex(0, 0)), A(nv, Complex(1, 0));
  std::vector<uint8_t> done(nv, 0);

  // The edge p -> q in p's tangent plane, with the edge's length.
  auto edge = [&](int p, int q) {
    const Vec3 e = mesh.vertices[q] - mesh.vertices[p];
    return e.norm() * unitOr(toComplex(F.vertexFrame(p).toLocal(e)), Complex(0, 0));
  };
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> front;
  auto pushNeighbours = [&](int q) {
    for (int r = F.neighbourBegin(q); r < F.neighbourEnd(q); ++r) {
      const int n = F.neighbour(r);
      if (!done[n]) front.push({std::abs(U[q] + A[q] * edge(q, n)), n});
    }
  };

  // The source face's corners are exact: planar offsets in the face, whose frame turned
  // to put the reference on +x is the source's.
  const Complex toSource =
      std::conj(unitOr(toComplex(F.faceFrame(sf).toLocal(reference)), Complex(1, 0)));
  const auto& corners = F.faceCorners(sf);
  const Vec2 at =
      source.bary[0] * corners[0] + source.bary[1] * corners[1] + source.bary[2] * corners[2];
  for (int k = 0; k < 3; ++k) {
    const int v = mesh.faces[sf][k];
    U[v] = toSource * toComplex(corners[k] - at);
    A[v] = toSource * F.vertexToFace(sf, k);
    done[v] = 1;
  }
  for (int k = 0; k < 3; ++k) pushNeighbours(mesh.faces[sf][k]);

  while (!front.empty()) {
    const auto [estimate, q] = front.top();
    front.pop();
    if (done[q]) continue;
    if (estimate > maxDistance) break;
    // Average the estimates from the visited neighbours, nearer ones weighing more.
    Complex u(0, 0), a(0, 0);
    double weights = 0;
    for (int r = F.neighbourBegin(q); r < F.neighbourEnd(q); ++r) {
      const int p = F.neighbour(r);
      if (!done[p]) continue;
      const Complex e = edge(p, q);
      const double w = 1 / std::max(std::norm(e), 1e-300);
      u += w * (U[p] + A[p] * e);
      a += w * A[p] * std::conj(F.neighbourToVertex(r));  // q's frame -> p's -> source's
      weights += w;
    }
    U[q] = u / weights;
    A[q] = unitOr(a, Complex(1, 0));
    done[q] = 1;
    pushNeighbours(q);
  }

  PolarMap map;
  map.distance.assign(nv, INFINITY);
  map.reference.assign(nv, Complex(1, 0));
  map.radial.assign(nv, Complex(1, 0));
  map.angle.assign(nv, Complex(1, 0));
  for (int v = 0; v < nv; ++v) {
    if (!done[v]) continue;
    map.distance[v] = std::abs(U[v]);
    map.reference[v] = std::conj(A[v]);
    map.angle[v] = unitOr(U[v], Complex(1, 0));
    map.radial[v] = map.reference[v] * map.angle[v];
  }
  return map;
}

}  // namespace fgsg::rt::field
