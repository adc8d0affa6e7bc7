#include "runtime/atlas/chart_parametrization.h"

#include "runtime/atlas/uv_geometry.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <complex>

namespace fgsg::rt::atlas {

namespace {

// The triangle in a plane of its own: its first edge along x, counter-clockwise.
std::array<Vec2, 3> flatten(const Vec3& p, const Vec3& q, const Vec3& r) {
  const Vec3 e1 = q - p, e2 = r - p;
  const double len = e1.norm();
  const Vec3 x = e1 / len;
  const Vec3 y = (e1.cross(e2)).cross(e1).normalized();
  return {Vec2(0, 0), Vec2(len, 0), Vec2(e2.dot(x), e2.dot(y))};
}

// The farthest of `candidates` from `from` (ties: the first).
int farthestFrom(const surface::SurfaceMesh& mesh, const ChartMesh& chart, int from,
                 const std::vector<int>& candidates) {
  int best = candidates.front();
  double bestDistance = -1;
  const Vec3& p = mesh.vertices[chart.meshVertex[from]];
  for (int v : candidates) {
    const double d = (mesh.vertices[chart.meshVertex[v]] - p).squaredNorm();
    if (d > bestDistance) best = v, bestDistance = d;
  }
  return best;
}

}  // namespace

bool parametrizeConformal(const surface::SurfaceMesh& mesh, const ChartMesh& chart,
                          std::vector<Vec2>& uv) {
  const int n = chart.vertexCount();
  uv.assign(n, Vec2::Zero());
  auto position = [&](int v) -> const Vec3& { return mesh.vertices[chart.meshVertex[v]]; };
  if (chart.triangles.size() == 1) {  // already flat: its own plane is exact
    const auto& t = chart.triangles[0];
    const auto flat = flatten(position(t[0]), position(t[1]), position(t[2]));
    for (int k = 0; k < 3; ++k) uv[t[k]] = flat[k];
    return true;
  }
  if (chart.boundaryEdges.empty()) return false;

  // Pins: two boundary vertices about as far apart as the boundary allows.
  std::vector<int> boundary;
  for (const auto& e : chart.boundaryEdges) boundary.push_back(e[0]);
  const int pinA = farthestFrom(mesh, chart, boundary.front(), boundary);
  const int pinB = farthestFrom(mesh, chart, pinA, boundary);
  if (pinA == pinB) return false;
  uv[pinA] = Vec2(0, 0);
  uv[pinB] = Vec2((position(pinB) - position(pinA)).norm(), 0);

  // Unknowns: z = u + iv of every vertex but the pins. The energy is z^H H z / 2 with H
  // Hermitian, so the system is half the size of the real one in (u, v) and its
  // factorization about half the work.
  using Complex = std::complex<double>;
  std::vector<int> unknown(n, -1);
  int free = 0;
  for (int v = 0; v < n; ++v)
    if (v != pinA && v != pinB) unknown[v] = free++;
  std::vector<Complex> z(n, 0.0);
  z[pinB] = Complex(uv[pinB].x(), 0);
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(free);
  std::vector<double> diagonal(free, 0.0);
  std::vector<Eigen::Triplet<Complex>> lower;  // the factorization reads the lower half
  lower.reserve(3 * chart.triangles.size() + chart.boundaryEdges.size() + free);
  // H(i, j) += w and H(j, i) += conj(w); a pinned partner moves the term to the right.
  auto couple = [&](int i, int j, Complex w) {
    const int a = unknown[i], b = unknown[j];
    if (a >= 0 && b >= 0) {
      if (a > b)
        lower.emplace_back(a, b, w);
      else
        lower.emplace_back(b, a, std::conj(w));
    } else if (a >= 0) {
      rhs[a] -= w * z[j];
    } else if (b >= 0) {
      rhs[b] -= std::conj(w) * z[i];
    }
  };

  // Dirichlet energy: half of cot(angle) times |z_i - z_j|^2 across the opposite edge.
  for (const auto& t : chart.triangles) {
    const auto flat = flatten(position(t[0]), position(t[1]), position(t[2]));
    const double twiceArea = twiceSignedArea(flat);
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = flat[(k + 1) % 3] - flat[k], b = flat[(k + 2) % 3] - flat[k];
      const double halfCot = 0.5 * a.dot(b) / twiceArea;
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      if (unknown[i] >= 0) diagonal[unknown[i]] += halfCot;
      if (unknown[j] >= 0) diagonal[unknown[j]] += halfCot;
      couple(i, j, -halfCot);
    }
  }
  // Minus the flat area: Im(conj(z_i) z_j) / 2 per boundary edge i -> j.
  for (const auto& e : chart.boundaryEdges) couple(e[0], e[1], Complex(0, 0.5));
  for (int a = 0; a < free; ++a) lower.emplace_back(a, a, diagonal[a]);

  Eigen::SparseMatrix<Complex> system(free, free);
  system.setFromTriplets(lower.begin(), lower.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Complex>, Eigen::Lower> solver(system);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::VectorXcd x = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !x.allFinite()) return false;
  for (int v = 0; v < n; ++v)
    if (unknown[v] >= 0) uv[v] = Vec2(x[unknown[v]].real(), x[unknown[v]].imag());
  return true;
}

}  // namespace fgsg::rt::atlas
