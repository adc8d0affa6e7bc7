// The mortar surface (mortar.h).
#include "runtime/cells/mortar.h"

#include <Eigen/SVD>

#include <cmath>

namespace fgsg::rt::cells {

Mesh mortarMesh(const surface::SurfaceMesh& m, double offset) {
  // Each vertex's move: the least-squares point x with n_i . x = offset for the normals
  // n_i of the distinct planes around it (a box corner: exactly its three faces).
  std::vector<Vec3> moved(m.vertices.size());
  for (size_t v = 0; v < m.vertices.size(); ++v) {
    std::vector<Vec3> planes;
    for (int f : m.facesAround(int(v))) {
      const Vec3& n = m.faceNormals[f];
      bool seen = false;
      for (const Vec3& p : planes) seen = seen || p.dot(n) > 1 - 1e-9;
      if (!seen) planes.push_back(n);
    }
    Eigen::MatrixXd a(planes.size(), 3);
    Eigen::VectorXd b = Eigen::VectorXd::Constant(Eigen::Index(planes.size()), offset);
    for (size_t k = 0; k < planes.size(); ++k) a.row(Eigen::Index(k)) = planes[k].transpose();
    Vec3 x = planes.empty() ? Vec3::Zero() : Vec3(a.jacobiSvd(Eigen::ComputeThinU | Eigen::ComputeThinV).solve(b));
    // A needle-sharp vertex would shoot far out: keep the move within three offsets.
    if (x.norm() > 3 * std::abs(offset)) x *= 3 * std::abs(offset) / x.norm();
    moved[v] = m.vertices[v] + x;
  }
  Mesh out;
  const size_t nf = m.faces.size();
  out.positions.resize(9 * nf);
  out.normals.resize(9 * nf);
  out.indices.resize(3 * nf);
  for (size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = moved[m.faces[f][k]];
      const Vec3& n = m.faceNormals[f];
      for (int c = 0; c < 3; ++c) {
        out.positions[9 * f + 3 * k + c] = float(p[c]);
        out.normals[9 * f + 3 * k + c] = float(n[c]);
      }
      out.indices[3 * f + k] = uint32_t(3 * f + k);
    }
  return out;
}

}  // namespace fgsg::rt::cells
