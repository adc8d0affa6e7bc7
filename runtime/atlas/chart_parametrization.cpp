#include "runtime/atlas/chart_parametrization.h"

#include "runtime/atlas/uv_geometry.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>

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

  // Unknowns: u and v of every vertex but the pins, interleaved (u_i at 2i, v_i at 2i+1).
  std::vector<int> unknown(n, -1);
  int free = 0;
  for (int v = 0; v < n; ++v)
    if (v != pinA && v != pinB) unknown[v] = free++;
  const int size = 2 * free;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(12 * chart.triangles.size() + 4 * chart.boundaryEdges.size());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
  // Adds `w` to the Hessian at (coordinate a of vertex i, coordinate b of vertex j); a
  // pinned partner moves the term to the right-hand side.
  auto add = [&](int i, int a, int j, int b, double w) {
    if (unknown[i] < 0) return;
    const int row = 2 * unknown[i] + a;
    if (unknown[j] < 0)
      rhs[row] -= w * uv[j][b];
    else
      entries.emplace_back(row, 2 * unknown[j] + b, w);
  };

  // Dirichlet energy: a quarter of cot(angle) times the squared difference across the
  // opposite edge, for u and for v alike.
  for (const auto& t : chart.triangles) {
    const auto flat = flatten(position(t[0]), position(t[1]), position(t[2]));
    const double twiceArea = twiceSignedArea(flat);
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = flat[(k + 1) % 3] - flat[k], b = flat[(k + 2) % 3] - flat[k];
      const double halfCot = 0.5 * a.dot(b) / twiceArea;
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      for (int c = 0; c < 2; ++c) {
        add(i, c, i, c, halfCot);
        add(j, c, j, c, halfCot);
        add(i, c, j, c, -halfCot);
        add(j, c, i, c, -halfCot);
      }
    }
  }
  // Minus the flat area: half of (u_i v_j - u_j v_i) per boundary edge i -> j.
  for (const auto& e : chart.boundaryEdges) {
    const int i = e[0], j = e[1];
    add(i, 0, j, 1, -0.5);
    add(j, 1, i, 0, -0.5);
    add(j, 0, i, 1, 0.5);
    add(i, 1, j, 0, 0.5);
  }

  Eigen::SparseMatrix<double> system(size, size);
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::VectorXd x = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !x.allFinite()) return false;
  for (int v = 0; v < n; ++v)
    if (unknown[v] >= 0) uv[v] = Vec2(x[2 * unknown[v]], x[2 * unknown[v] + 1]);
  return true;
}

}  // namespace fgsg::rt::atlas
