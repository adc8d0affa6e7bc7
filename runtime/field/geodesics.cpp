#include "runtime/field/geodesics.h"

#include "runtime/field/complex_direction.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::field {

namespace {

using Complex = std::complex<double>;
// Regularises the Poisson problem, singular on a closed mesh (constants): adds this times
// M / t, small against the Laplacian's O(1) entries. It shifts the solution by a near
// constant, which the distance's shift to zero at the source removes.
constexpr double kPoissonRegularisation = 1e-8;
// A source barycentric coordinate this close to 1 puts the source on that vertex.
constexpr double kOnVertex = 1e-9;

}  // namespace

HeatGeodesics::HeatGeodesics(std::shared_ptr<const TangentFrames> frames, double timeScale)
    : frames_(std::move(frames)) {
  const SurfaceMesh& mesh = frames_->mesh();
  const int nv = int(mesh.vertexCount());
  if (nv == 0 || mesh.faceCount() == 0) {
    error_ = "the surface has no faces";
    return;
  }
  t_ = timeScale * mesh.meanEdgeLength * mesh.meanEdgeLength;
  mass_.assign(nv, 0.0);
  cot_.resize(mesh.faceCount());
  // Cotangent weights per ring entry (i -> j), from the two faces beside the edge.
  std::vector<double>& weight = weight_;
  weight.assign(frames_->neighbourEnd(nv - 1), 0.0);
  edge_.resize(weight.size());
  for (int i = 0; i < nv; ++i)
    for (int r = frames_->neighbourBegin(i); r < frames_->neighbourEnd(i); ++r) {
      const Vec3 e = mesh.vertices[frames_->neighbour(r)] - mesh.vertices[i];
      edge_[r] = e.norm() * unitOr(toComplex(frames_->vertexFrame(i).toLocal(e)), Complex(0, 0));
    }
  auto ringIndex = [&](int i, int j) {
    const int begin = frames_->neighbourBegin(i), end = frames_->neighbourEnd(i);
    int lo = begin, hi = end;
    while (lo < hi) {  // rings are sorted by neighbour
      const int mid = (lo + hi) / 2;
      if (frames_->neighbour(mid) < j) lo = mid + 1; else hi = mid;
    }
    return lo;
  };
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.vertices[t[(k + 1) % 3]] - mesh.vertices[t[k]];
      const Vec3 b = mesh.vertices[t[(k + 2) % 3]] - mesh.vertices[t[k]];
      const double sine = a.cross(b).norm();
      cot_[f][k] = sine > 0 ? a.dot(b) / sine : 0.0;
      mass_[t[k]] += mesh.faceAreas[f] / 3;
    }
    for (int k = 0; k < 3; ++k) {
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];  // the edge opposite corner k
      weight[ringIndex(i, j)] += 0.5 * cot_[f][k];
      weight[ringIndex(j, i)] += 0.5 * cot_[f][k];
    }
  }
  std::vector<Eigen::Triplet<double>> heat, poisson;
  std::vector<Eigen::Triplet<Complex>> connection;
  const size_t entries = weight.size() + nv;
  heat.reserve(entries);
  poisson.reserve(entries);
  connection.reserve(entries);
  for (int i = 0; i < nv; ++i) {
    double diagonal = 0;
    for (int r = frames_->neighbourBegin(i); r < frames_->neighbourEnd(i); ++r) {
      const int j = frames_->neighbour(r);
      const double w = weight[r];
      diagonal += w;
      heat.emplace_back(i, j, -t_ * w);
      poisson.emplace_back(i, j, -w);
      connection.emplace_back(i, j, -t_ * w * frames_->neighbourToVertex(r));
    }
    heat.emplace_back(i, i, mass_[i] + t_ * diagonal);
    poisson.emplace_back(i, i, diagonal + kPoissonRegularisation * mass_[i] / t_);
    connection.emplace_back(i, i, Complex(mass_[i] + t_ * diagonal, 0));
  }
  Eigen::SparseMatrix<double> A(nv, nv), P(nv, nv);
  Eigen::SparseMatrix<Complex> C(nv, nv);
  A.setFromTriplets(heat.begin(), heat.end());
  P.setFromTriplets(poisson.begin(), poisson.end());
  C.setFromTriplets(connection.begin(), connection.end());
  heat_.compute(A);
  poisson_.compute(P);
  vectorHeat_.compute(C);
  bool ok = heat_.info() == Eigen::Success && poisson_.info() == Eigen::Success &&
            vectorHeat_.info() == Eigen::Success;
  // With a boundary, heat flow with zero flux across it (Neumann) bends the distance's
  // level sets toward the boundary, with zero heat on it (Dirichlet) away from it; their
  // average is much better than either (Crane et al. 2013, §3.3).
  for (int i = 0; i < nv; ++i) hasBoundary_ = hasBoundary_ || mesh.boundaryVertex[i];
  if (hasBoundary_) {
    std::vector<Eigen::Triplet<double>> dirichlet;
    dirichlet.reserve(heat.size());
    for (const auto& e : heat)
      if (!mesh.boundaryVertex[e.row()] && !mesh.boundaryVertex[e.col()]) dirichlet.push_back(e);
    for (int i = 0; i < nv; ++i)
      if (mesh.boundaryVertex[i]) dirichlet.emplace_back(i, i, 1.0);
    Eigen::SparseMatrix<double> D(nv, nv);
    D.setFromTriplets(dirichlet.begin(), dirichlet.end());
    heatDirichlet_.compute(D);
    ok = ok && heatDirichlet_.info() == Eigen::Success;
  }
  if (!ok) error_ = "the surface's Laplacian could not be factorised (degenerate triangles?)";
}

std::vector<double> HeatGeodesics::solveDistance(const SurfacePoint& source,
                                                 Eigen::VectorXd* neumannHeat) const {
  const SurfaceMesh& mesh = frames_->mesh();
  const int nv = int(mesh.vertexCount());
  const auto& s = mesh.faces[source.face];
  Eigen::VectorXd u0 = Eigen::VectorXd::Zero(nv);
  for (int k = 0; k < 3; ++k) u0[s[k]] += source.bary[k];
  Eigen::VectorXd u = heat_.solve(u0);
  if (neumannHeat) *neumannHeat = u;
  if (hasBoundary_) {
    for (int i = 0; i < nv; ++i)
      if (mesh.boundaryVertex[i]) u0[i] = 0;
    u = 0.5 * (u + heatDirichlet_.solve(u0));
  }

  // X = -grad u / |grad u| per face; its integrated divergence per vertex.
  Eigen::VectorXd divergence = Eigen::VectorXd::Zero(nv);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto& t = mesh.faces[f];
    const double area = mesh.faceAreas[f];
    if (area <= 0) continue;
    const Vec3& n = mesh.faceNormals[f];
    Vec3 grad = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      const Vec3 opposite = mesh.vertices[t[(k + 2) % 3]] - mesh.vertices[t[(k + 1) % 3]];
      grad += u[t[k]] * n.cross(opposite) / (2 * area);
    }
    const double len = grad.norm();
    if (len <= 0) continue;
    const Vec3 X = -grad / len;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e1 = mesh.vertices[t[(k + 1) % 3]] - mesh.vertices[t[k]];
      const Vec3 e2 = mesh.vertices[t[(k + 2) % 3]] - mesh.vertices[t[k]];
      divergence[t[k]] += 0.5 * (cot_[f][(k + 2) % 3] * e1.dot(X) +
                                 cot_[f][(k + 1) % 3] * e2.dot(X));
    }
  }
  // L phi = -div X (L positive semi-definite: L = -Laplace).
  const Eigen::VectorXd phi = poisson_.solve(-divergence);
  // phi is the distance up to a constant. The heat's spread rounds off the cone's tip, so
  // the constant is taken from the source face's corners, whose distances are planar.
  const auto& corners = frames_->faceCorners(source.face);
  const Vec2 at = source.bary[0] * corners[0] + source.bary[1] * corners[1] +
                  source.bary[2] * corners[2];
  double atSource = 0;
  for (int k = 0; k < 3; ++k) atSource += (phi[s[k]] - (corners[k] - at).norm()) / 3;
  std::vector<double> rho(nv);
  for (int i = 0; i < nv; ++i) rho[i] = std::max(0.0, phi[i] - atSource);
  return rho;
}

std::vector<double> HeatGeodesics::distance(const SurfacePoint& source) const {
  return solveDistance(source, nullptr);
}

PolarMap HeatGeodesics::polarMap(const SurfacePoint& source, const Vec3& reference) const {
  // Kept by the exact source and reference: a map taken again is the one solved.
  const auto same = [&](const PolarMemo& m) {
    return m.face == source.face && m.bary == source.bary && m.reference == reference;
  };
  {
    std::lock_guard<std::mutex> lock(polarMemoMutex_);
    const auto it = std::find_if(polarMemo_.begin(), polarMemo_.end(), same);
    if (it != polarMemo_.end()) {
      PolarMemo found = *it;
      polarMemo_.erase(it);
      polarMemo_.push_back(found);  // the newest now
      return *found.map;
    }
  }
  auto map = std::make_shared<const PolarMap>(solvePolarMap(source, reference));
  const size_t bytes = map->distance.size() * (sizeof(double) + 3 * sizeof(Rot2));
  const size_t kept = kPolarMemoBytes / std::max<size_t>(bytes, 1);
  std::lock_guard<std::mutex> lock(polarMemoMutex_);
  if (kept > 0 && std::none_of(polarMemo_.begin(), polarMemo_.end(), same)) {
    if (polarMemo_.size() >= kept) polarMemo_.erase(polarMemo_.begin());
    polarMemo_.push_back({source.face, source.bary, reference, map});
  }
  return *map;
}

PolarMap HeatGeodesics::solvePolarMap(const SurfacePoint& source, const Vec3& reference) const {
  const SurfaceMesh& mesh = frames_->mesh();
  const TangentFrames& F = *frames_;
  const int nv = int(mesh.vertexCount());
  const int sf = source.face;
  const auto& s = mesh.faces[sf];
  PolarMap map;
  Eigen::VectorXd u;
  map.distance = solveDistance(source, &u);

  // Two vector heat flows with the same factorisation: column 0 carries the reference
  // vector; column 1 the affine part of the source's position (see the header), started
  // at the source face's corners with the source's position relative to each of them.
  const auto& corners = F.faceCorners(sf);
  const Vec2 at =
      source.bary[0] * corners[0] + source.bary[1] * corners[1] + source.bary[2] * corners[2];
  const Complex refFace = unitOr(toComplex(F.faceFrame(sf).toLocal(reference)), Complex(1, 0));
  Eigen::MatrixXcd rhs = Eigen::MatrixXcd::Zero(nv, 2);
  for (int k = 0; k < 3; ++k) {
    const Complex back = std::conj(F.vertexToFace(sf, k));
    rhs(s[k], 0) += source.bary[k] * back * refFace;
    rhs(s[k], 1) += source.bary[k] * back * toComplex(at - corners[k]);
  }
  // The translations of the affine connection, weighted by the scalar heat they carry.
  for (int i = 0; i < nv; ++i)
    for (int r = F.neighbourBegin(i); r < F.neighbourEnd(i); ++r)
      rhs(i, 1) += t_ * weight_[r] * edge_[r] * u[F.neighbour(r)];
  const Eigen::MatrixXcd sol = vectorHeat_.solve(rhs);

  map.reference.resize(nv);
  map.radial.resize(nv);
  map.angle.resize(nv);
  for (int i = 0; i < nv; ++i) {
    map.reference[i] = unitOr(sol(i, 0), Complex(1, 0));
    // sol(i, 1) / u[i] is where the source lies seen from vertex i: the geodesic arrives
    // from the opposite direction.
    map.radial[i] = unitOr(-sol(i, 1), map.reference[i]);
    map.angle[i] = map.radial[i] * std::conj(map.reference[i]);
  }
  for (int k = 0; k < 3; ++k)
    if (source.bary[k] >= 1 - kOnVertex) {
      map.angle[s[k]] = Complex(1, 0);
      map.distance[s[k]] = 0;
    }
  return map;
}

}  // namespace fgsg::rt::field
