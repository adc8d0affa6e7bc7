#include "runtime/field/curvature.h"

#include <Eigen/Dense>

namespace fgsg::rt::field {

TangentField curvatureTensor(std::shared_ptr<const TangentFrames> frames) {
  const SurfaceMesh& mesh = frames->mesh();
  const size_t nv = mesh.vertexCount();
  std::vector<Mat2> sum(nv, Mat2::Zero());
  std::vector<double> weight(nv, 0.0);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto& t = mesh.faces[f];
    const Frame& frame = frames->faceFrame(int(f));
    // Least squares for II = [[a, b], [b, c]]: two equations per edge.
    Eigen::Matrix<double, 6, 3> A;
    Eigen::Matrix<double, 6, 1> rhs;
    for (int k = 0; k < 3; ++k) {
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      const Vec2 e = frame.toLocal(mesh.vertices[j] - mesh.vertices[i]);
      const Vec2 dn = frame.toLocal(mesh.vertexNormals[j] - mesh.vertexNormals[i]);
      A.row(2 * k) << e.x(), e.y(), 0;
      A.row(2 * k + 1) << 0, e.x(), e.y();
      rhs[2 * k] = dn.x();
      rhs[2 * k + 1] = dn.y();
    }
    const Eigen::Matrix3d normal = A.transpose() * A;
    Eigen::LDLT<Eigen::Matrix3d> solver(normal);
    if (mesh.faceAreas[f] <= 0 || solver.info() != Eigen::Success) continue;
    const Vec3 abc = solver.solve(A.transpose() * rhs);
    if (!abc.allFinite()) continue;
    Mat2 II;
    II << abc[0], abc[1], abc[1], abc[2];
    for (int k = 0; k < 3; ++k) {
      // The face's II in the corner's frame: the inverse of the vertex-to-face transport.
      sum[t[k]] += mesh.faceAreas[f] * rotate(std::conj(frames->vertexToFace(int(f), k)), II);
      weight[t[k]] += mesh.faceAreas[f];
    }
  }
  std::vector<Mat2> values(nv);
  for (size_t v = 0; v < nv; ++v)
    values[v] = weight[v] > 0 ? Mat2(sum[v] / weight[v]) : Mat2::Zero();
  TangentField field(std::move(frames), FieldType::Tensor);
  field.setVertexTensors(std::move(values));
  return field;
}

Curvatures curvaturesAt(const TangentField& curvature, const SurfacePoint& p) {
  const LocalEigen e = eigenOf(curvature.tensor(p));
  return {e.value2, e.value1, 0.5 * (e.value1 + e.value2), e.value1 * e.value2};
}

}  // namespace fgsg::rt::field
