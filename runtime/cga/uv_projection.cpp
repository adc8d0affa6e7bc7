#include "runtime/cga/uv_projection.h"

#include <algorithm>
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

std::array<double, 2> projectPoint(const UvProjection& projection, const Vec3& world, const Vec3& facing0) {
  const Mat3 toFrame = projection.axes.transpose();
  const Vec3 local = toFrame * (world - projection.origin);
  double u, w;
  if (projection.planar) {
    u = local.x(), w = local.y();
  } else {
    const Vec3 facing = toFrame * facing0;
    Eigen::Index k;
    facing.cwiseAbs().maxCoeff(&k);
    const double side = facing[k] < 0 ? -1.0 : 1.0;
    // (u, v) on the plane the face looks along, as seen from in front of it: v stays up
    // (Y) on the upright planes, and runs against Z on the XZ plane (a top seen from above).
    if (k == 2) u = side * local.x(), w = local.y();
    else if (k == 0) u = -side * local.z(), w = local.y();
    else u = side * local.x(), w = -local.z();
  }
  u /= projection.tileWidth;
  w /= projection.tileHeight;
  const auto& t = projection.uvTransform;
  static constexpr std::array<double, 6> kIdentity{1, 0, 0, 0, 1, 0};
  if (t == kIdentity) return {u, w};  // bit for bit as before the uv operations
  return {t[0] * u + t[1] * w + t[2], t[3] * u + t[4] * w + t[5]};
}

void projectTexcoords(Mesh& mesh, const Scope& scope, const UvProjection& projection) {
  projectTexcoordsInto(mesh, scope, projection, mesh.texcoords);
}

void projectTexcoordsInto(const Mesh& mesh, const Scope& scope, const UvProjection& projection,
                          MeshArray<float>& into) {
  const size_t n = mesh.vertexCount();
  into.resize(2 * n);
  const Vec3& S = scope.S;
  // A unit-box normal maps to the world by the cofactor of axes * diag(S) (defined for a
  // flat scope too): axes * (Sy Sz nx, Sx Sz ny, Sx Sy nz), up to a positive factor.
  const Vec3 normalScale(S.y() * S.z(), S.x() * S.z(), S.x() * S.y());
  for (size_t v = 0; v < n; ++v) {
    const Vec3 q(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
    const Vec3 n0(mesh.normals[3 * v], mesh.normals[3 * v + 1], mesh.normals[3 * v + 2]);
    const Vec3 world = scope.P + scope.axes * S.cwiseProduct(q);
    const std::array<double, 2> uv = projectPoint(projection, world, scope.axes * normalScale.cwiseProduct(n0));
    into[2 * v] = float(uv[0]);
    into[2 * v + 1] = float(uv[1]);
  }
}

std::array<double, 4> uvRangeOfScope(const UvProjection& projection, const Scope& scope) {
  UvProjection planar = projection;
  planar.planar = true;
  std::array<double, 4> r{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 q(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    const std::array<double, 2> uv = projectPoint(planar, scope.P + scope.axes * scope.S.cwiseProduct(q), Vec3::UnitZ());
    r[0] = std::min(r[0], uv[0]), r[1] = std::max(r[1], uv[0]);
    r[2] = std::min(r[2], uv[1]), r[3] = std::max(r[3], uv[1]);
  }
  return r;
}

}  // namespace fgsg::rt::cga
