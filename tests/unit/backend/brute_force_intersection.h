// An independent check for collision-tested instancing: every pair of instances is
// compared triangle against triangle (no BVH, no FCL), plus an even-odd ray test for one
// instance lying wholly inside another. Slow and simple on purpose: it judges the
// collision world's answers from outside.
#pragma once

#include "runtime/assets.h"
#include "runtime/instances.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::test {

using V3 = Eigen::Vector3d;

struct WorldMesh {
  std::vector<std::array<V3, 3>> triangles;
  V3 lo = V3::Constant(INFINITY), hi = V3::Constant(-INFINITY);
  bool closed = false;
};

inline WorldMesh worldMesh(const rt::Mesh& mesh, const rt::Instance& inst) {
  const Eigen::Matrix4d M = Eigen::Map<const Eigen::Matrix4d>(inst.transform.data());
  WorldMesh w;
  std::map<std::array<float, 3>, int> weldedId;
  std::map<std::pair<int, int>, int> edgeUse;
  auto id = [&](uint32_t v) {
    std::array<float, 3> p{mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
    return weldedId.emplace(p, int(weldedId.size())).first->second;
  };
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    std::array<V3, 3> tri;
    int ids[3];
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.indices[3 * t + k];
      const Eigen::Vector4d p = M * Eigen::Vector4d(mesh.positions[3 * v], mesh.positions[3 * v + 1],
                                                    mesh.positions[3 * v + 2], 1.0);
      tri[k] = p.head<3>();
      w.lo = w.lo.cwiseMin(tri[k]);
      w.hi = w.hi.cwiseMax(tri[k]);
      ids[k] = id(v);
    }
    for (int k = 0; k < 3; ++k) {
      const int a = ids[k], b = ids[(k + 1) % 3];
      ++edgeUse[{std::min(a, b), std::max(a, b)}];
    }
    w.triangles.push_back(tri);
  }
  w.closed = !edgeUse.empty();
  for (const auto& [e, n] : edgeUse) w.closed = w.closed && n == 2;
  return w;
}

// Does the closed segment p-q meet the triangle? Coplanar segments are left to the
// coplanar test. `eps` keeps rounding from inventing contacts between separate shapes.
inline bool segmentHitsTriangle(const V3& p, const V3& q, const std::array<V3, 3>& t, double eps) {
  const V3 n = (t[1] - t[0]).cross(t[2] - t[0]);
  const double len = n.norm();
  if (len == 0) return false;
  const double dp = n.dot(p - t[0]) / len, dq = n.dot(q - t[0]) / len;
  if ((dp > eps && dq > eps) || (dp < -eps && dq < -eps)) return false;
  if (std::abs(dp) <= eps && std::abs(dq) <= eps) return false;  // coplanar
  const V3 x = p + (q - p) * (dp / (dp - dq));
  for (int k = 0; k < 3; ++k) {
    const V3 e = t[(k + 1) % 3] - t[k];
    if (n.dot(e.cross(x - t[k])) / len < -eps * e.norm()) return false;
  }
  return true;
}

// Coplanar triangles: projected on their dominant plane, do they overlap?
inline bool coplanarOverlap(const std::array<V3, 3>& a, const std::array<V3, 3>& b, double eps) {
  const V3 n = (a[1] - a[0]).cross(a[2] - a[0]);
  const V3 nb = (b[1] - b[0]).cross(b[2] - b[0]);
  if (n.norm() == 0 || nb.norm() == 0) return false;
  if (n.normalized().cross(nb.normalized()).norm() > 1e-9) return false;
  if (std::abs(n.normalized().dot(b[0] - a[0])) > eps) return false;
  int drop = 0;
  n.cwiseAbs().maxCoeff(&drop);
  auto flat = [&](const V3& v) { return Eigen::Vector2d(v[(drop + 1) % 3], v[(drop + 2) % 3]); };
  auto cross2 = [](Eigen::Vector2d u, Eigen::Vector2d v) { return u.x() * v.y() - u.y() * v.x(); };
  auto inside = [&](const std::array<V3, 3>& t, const V3& p) {
    const Eigen::Vector2d q = flat(p);
    double s[3];
    for (int k = 0; k < 3; ++k) s[k] = cross2(flat(t[(k + 1) % 3]) - flat(t[k]), q - flat(t[k]));
    return (s[0] > eps && s[1] > eps && s[2] > eps) || (s[0] < -eps && s[1] < -eps && s[2] < -eps);
  };
  for (int i = 0; i < 3; ++i) {
    if (inside(a, b[i]) || inside(b, a[i])) return true;
    for (int j = 0; j < 3; ++j) {  // proper crossings of edges
      const Eigen::Vector2d p = flat(a[i]), r = flat(a[(i + 1) % 3]) - p;
      const Eigen::Vector2d q = flat(b[j]), s = flat(b[(j + 1) % 3]) - q;
      const double d = cross2(r, s);
      if (std::abs(d) < 1e-300) continue;
      const double t = cross2(q - p, s) / d, u = cross2(q - p, r) / d;
      if (t > eps && t < 1 - eps && u > eps && u < 1 - eps) return true;
    }
  }
  return false;
}

inline bool trianglesIntersect(const std::array<V3, 3>& a, const std::array<V3, 3>& b, double eps) {
  for (int k = 0; k < 3; ++k) {
    if (segmentHitsTriangle(a[k], a[(k + 1) % 3], b, eps)) return true;
    if (segmentHitsTriangle(b[k], b[(k + 1) % 3], a, eps)) return true;
  }
  return coplanarOverlap(a, b, eps);
}

// Even-odd count along a fixed ray (another direction than the collision world's).
inline bool pointInside(const WorldMesh& m, const V3& p) {
  const V3 d = V3(0.3119, 0.7331, 0.6043).normalized();
  int crossings = 0;
  for (const auto& t : m.triangles) {
    const V3 e1 = t[1] - t[0], e2 = t[2] - t[0], h = d.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-300) continue;
    const V3 s = p - t[0];
    const double u = s.dot(h) / det;
    const V3 qv = s.cross(e1);
    const double v = d.dot(qv) / det;
    if (u < 0 || v < 0 || u + v > 1) continue;
    if (e2.dot(qv) / det > 0) ++crossings;
  }
  return crossings % 2 == 1;
}

// The pairs (i, j), i < j, of the listed instances that intersect or nest.
inline std::vector<std::pair<size_t, size_t>> intersectingPairs(
    const rt::InstanceList& list, const std::vector<size_t>& which, rt::AssetLibrary& library,
    double eps = 1e-9) {
  std::vector<WorldMesh> meshes;
  for (size_t i : which) {
    std::string error;
    const int mesh = library.resolve(list.assets[list.instances[i].asset], error);
    if (mesh < 0) throw std::runtime_error(error);
    meshes.push_back(worldMesh(library.mesh(mesh), list.instances[i]));
  }
  std::vector<std::pair<size_t, size_t>> hits;
  for (size_t x = 0; x < meshes.size(); ++x)
    for (size_t y = x + 1; y < meshes.size(); ++y) {
      const WorldMesh &a = meshes[x], &b = meshes[y];
      if ((a.lo.array() > b.hi.array() + eps).any() || (b.lo.array() > a.hi.array() + eps).any()) continue;
      bool hit = false;
      for (const auto& ta : a.triangles) {
        for (const auto& tb : b.triangles)
          if (trianglesIntersect(ta, tb, eps)) {
            hit = true;
            break;
          }
        if (hit) break;
      }
      if (!hit && a.closed && !b.triangles.empty()) hit = pointInside(a, b.triangles[0][0]);
      if (!hit && b.closed && !a.triangles.empty()) hit = pointInside(b, a.triangles[0][0]);
      if (hit) hits.emplace_back(which[x], which[y]);
    }
  return hits;
}

}  // namespace fgsg::test
