// Geodesic polar coordinates around a surface point (FGSG §4.2 spreads design elements
// over the surface with them), by heat flow:
//   distance rho: the heat method (Crane, Weischedel, Wardetzky 2013) — diffuse heat u
//     from the source for a short time t = h^2 (h the mean edge length; on a mesh with a
//     boundary the mean of the zero-flux and zero-value solutions), normalise its
//     gradient per face, and solve a Poisson problem for the function with that gradient;
//     the constant is fixed by the source face's corners, whose distances are planar;
//   the reference direction carried along the geodesics: the vector heat method (Sharp,
//     Soliman, Crane 2019) — diffuse the source's vector for the same time with the
//     connection Laplacian (the vertex-to-vertex transports of TangentFrames), normalise;
//   the direction of the geodesic at each vertex: where the source lies seen from the
//     vertex, by the affine heat method (Soliman, Sharp 2025, "local" variant) — diffuse
//     the homogeneous point (source, 1) with the affine connection that carries a point in
//     j's tangent plane to i's as r_ij p + e_ij (e_ij the edge i -> j in i's frame). Its
//     weight part is the scalar heat u, its point part solves the vector heat system with
//     the translations as a source term; their ratio is the source's position in the
//     vertex's tangent plane, and the geodesic arrives from the opposite direction;
//   theta = the angle from the transported reference to that direction: both were carried
//     along the same geodesic, so it is the angle they made at the source.
// Exact on a flat mesh; on curved ones an approximation (measured on a unit icosphere with
// 2562 vertices: angle within 0.5 degrees and distance within 0.015 up to 0.87 pi from
// the source; near the cut locus the angle is meaningless anyway). The three matrices
// (heat, Poisson, vector heat; a fourth with a boundary) are factorised once per mesh
// (SimplicialLDLT); each source then costs four or five back-substitutions.
#pragma once

#include "runtime/field/tangent_frames.h"

#include <Eigen/Sparse>

#include <complex>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace fgsg::rt::field {

struct PolarMap {
  std::vector<double> distance;  // rho per vertex, >= 0
  // Unit complex numbers in each vertex's frame: the source's reference direction carried
  // to the vertex, and the direction in which the geodesic from the source leaves it.
  std::vector<Rot2> reference, radial;
  // e^(i theta): the geodesic's direction at the source relative to the reference, i.e.
  // radial / reference. 1 at a vertex the source sits on (undefined there).
  std::vector<Rot2> angle;
};

class HeatGeodesics {
 public:
  // Factorises the operators; ok() says whether that worked (it fails only for meshes
  // with degenerate geometry). `timeScale` multiplies t = h^2.
  explicit HeatGeodesics(std::shared_ptr<const TangentFrames> frames, double timeScale = 1);
  HeatGeodesics(const HeatGeodesics&) = delete;
  HeatGeodesics& operator=(const HeatGeodesics&) = delete;

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  const TangentFrames& frames() const { return *frames_; }

  // Geodesic distance from the source to every vertex.
  std::vector<double> distance(const SurfacePoint& source) const;
  // Polar coordinates around the source; the reference direction (world, projected onto
  // the source face's plane; the face frame's e1 if that leaves nothing) is theta = 0.
  // The last maps asked for are kept (at most kPolarMemoBytes, the newest): fgsg view
  // designs a field again on the same geodesics after each edit of an element (#49), and
  // the elements that did not change are not solved again.
  PolarMap polarMap(const SurfacePoint& source, const Vec3& reference) const;

 private:
  static constexpr size_t kPolarMemoBytes = size_t(64) << 20;
  struct PolarMemo {
    int face;
    Vec3 bary, reference;
    std::shared_ptr<const PolarMap> map;
  };
  PolarMap solvePolarMap(const SurfacePoint& source, const Vec3& reference) const;
  // The distance; `neumannHeat` receives the heat flow with zero flux across a boundary.
  std::vector<double> solveDistance(const SurfacePoint& source,
                                    Eigen::VectorXd* neumannHeat) const;

  using Complex = std::complex<double>;
  std::shared_ptr<const TangentFrames> frames_;
  std::string error_;
  double t_ = 0;
  std::vector<double> mass_;
  std::vector<std::array<double, 3>> cot_;  // cotangent of each face corner's angle
  // Per ring entry (i -> j, TangentFrames' neighbour ranges): the cotangent weight and the
  // edge to j in i's frame (projected onto the tangent plane, keeping its length).
  std::vector<double> weight_;
  std::vector<Complex> edge_;
  bool hasBoundary_ = false;
  // Factorised, not iterated: heat decays exponentially with distance (about e^(-rho/h))
  // and the distance needs its direction hundreds of orders of magnitude below the peak,
  // which only a direct solve keeps.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> heat_, heatDirichlet_, poisson_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Complex>> vectorHeat_;
  mutable std::mutex polarMemoMutex_;
  mutable std::vector<PolarMemo> polarMemo_;  // oldest first
};

}  // namespace fgsg::rt::field
