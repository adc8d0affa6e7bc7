#include "runtime/field/scalar_field.h"

#include <cmath>

namespace fgsg::rt::field {

double ScalarField::at(const SurfaceMesh& mesh, const surface::SurfacePoint& p) const {
  const auto& f = mesh.faces[p.face];
  return p.bary[0] * values[f[0]] + p.bary[1] * values[f[1]] + p.bary[2] * values[f[2]];
}

Vec3 ScalarField::gradient(const SurfaceMesh& mesh, int face) const {
  const auto& f = mesh.faces[face];
  const Vec3 &p0 = mesh.vertices[f[0]], &p1 = mesh.vertices[f[1]], &p2 = mesh.vertices[f[2]];
  const Vec3 normal = (p1 - p0).cross(p2 - p0);
  const double twiceArea = normal.norm();
  if (!(twiceArea > 0)) return Vec3::Zero();
  const Vec3 n = normal / twiceArea;
  // Each value times its opposite edge turned a quarter in the plane (counter-clockwise).
  return (values[f[0]] * n.cross(p2 - p1) + values[f[1]] * n.cross(p0 - p2) + values[f[2]] * n.cross(p1 - p0)) /
         twiceArea;
}

TangentField ScalarField::gradientField(std::shared_ptr<const TangentFrames> frames) const {
  const SurfaceMesh& mesh = frames->mesh();
  std::vector<Vec3> sum(mesh.vertexCount(), Vec3::Zero());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const Vec3 g = mesh.faceAreas[f] * gradient(mesh, int(f));
    for (int v : mesh.faces[f]) sum[v] += g;
  }
  TangentField field(std::move(frames), FieldType::Vector);
  for (size_t v = 0; v < sum.size(); ++v) field.setVertexVectorWorld(int(v), sum[v]);
  return field;
}

ScalarField scalarFromPicture(const SurfaceMesh& mesh, const Picture& picture) {
  ScalarField out;
  out.values.reserve(mesh.vertexCount());
  for (const Vec3& v : mesh.vertices) out.values.push_back(picture.under(mesh, v));
  return out;
}

}  // namespace fgsg::rt::field
