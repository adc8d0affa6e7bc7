#include "runtime/cga/uv_projection.h"

#include <cmath>

namespace fgsg::rt::cga {

UvProjection projectionAt(const Scope& scope, double tileWidth, double tileHeight, uint32_t texture) {
  UvProjection p;
  p.origin = scope.P;
  p.axes = scope.axes;
  const bool overScope = tileWidth == 0 && tileHeight == 0;
  p.tileWidth = overScope ? scope.S.x() : tileWidth;
  p.tileHeight = overScope ? scope.S.y() : tileHeight;
  if (!(p.tileWidth > 0)) p.tileWidth = 1;  // a flat scope: one image per metre
  if (!(p.tileHeight > 0)) p.tileHeight = 1;
  p.texture = texture;
  return p;
}

void projectTexcoords(Mesh& mesh, const Scope& scope, const UvProjection& projection) {
  const size_t n = mesh.vertexCount();
  mesh.texcoords.resize(2 * n);
  const Vec3& S = scope.S;
  // A unit-box normal maps to the world by the cofactor of axes * diag(S) (defined for a
  // flat scope too): axes * (Sy Sz nx, Sx Sz ny, Sx Sy nz), up to a positive factor.
  const Vec3 normalScale(S.y() * S.z(), S.x() * S.z(), S.x() * S.y());
  const Mat3 toFrame = projection.axes.transpose();
  for (size_t v = 0; v < n; ++v) {
    const Vec3 q(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
    const Vec3 n0(mesh.normals[3 * v], mesh.normals[3 * v + 1], mesh.normals[3 * v + 2]);
    const Vec3 world = scope.P + scope.axes * S.cwiseProduct(q);
    const Vec3 local = toFrame * (world - projection.origin);
    const Vec3 facing = toFrame * (scope.axes * normalScale.cwiseProduct(n0));
    Eigen::Index k;
    facing.cwiseAbs().maxCoeff(&k);
    const double side = facing[k] < 0 ? -1.0 : 1.0;
    // (u, v) on the plane the face looks along, as seen from in front of it: v stays up
    // (Y) on the upright planes, and runs against Z on the XZ plane (a top seen from above).
    double u, w;
    if (k == 2) u = side * local.x(), w = local.y();
    else if (k == 0) u = -side * local.z(), w = local.y();
    else u = side * local.x(), w = -local.z();
    mesh.texcoords[2 * v] = float(u / projection.tileWidth);
    mesh.texcoords[2 * v + 1] = float(w / projection.tileHeight);
  }
}

}  // namespace fgsg::rt::cga
