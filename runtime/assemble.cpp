#include "runtime/assemble.h"

#include "runtime/marching/curve_bend.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace fgsg::rt {

namespace {

using Eigen::Matrix3d;
using Eigen::Matrix4d;
using Eigen::Vector3d;

constexpr uint32_t kUnused = UINT32_MAX;

// How one instance maps its asset into the world.
struct Placement {
  Matrix4d M;
  Matrix3d normalMatrix;  // cofactor of the linear part, sign-fixed for mirrors
  bool flip = false;      // a mirroring transform: reverse winding to keep it outward
  // A smooth terminal (Instance::curve): bent along its curve after M.
  std::optional<marching::CurveBend> bend;
};

Placement placementOf(const Instance& inst, const InstanceList& list) {
  Placement p;
  p.M = Eigen::Map<const Matrix4d>(inst.transform.data());  // column-major like Eigen
  const Matrix3d A = p.M.block<3, 3>(0, 0);
  // cof(A) = [a2 x a3, a3 x a1, a1 x a2] satisfies (A u) x (A v) = cof(A) (u x v): it maps a
  // normal to the transformed surface's normal even when A is singular (a flattened box),
  // where the usual inverse transpose does not exist.
  const Vector3d a1 = A.col(0), a2 = A.col(1), a3 = A.col(2);
  p.normalMatrix.col(0) = a2.cross(a3);
  p.normalMatrix.col(1) = a3.cross(a1);
  p.normalMatrix.col(2) = a1.cross(a2);
  // A mirror (det < 0) turns outward normals and counter-clockwise winding inside out;
  // flipping both restores them. The tolerance keeps a flattened (det ~ 0) box unflipped.
  const double scale = a1.norm() * a2.norm() * a3.norm();
  p.flip = A.determinant() < -1e-9 * scale;
  if (p.flip) p.normalMatrix = -p.normalMatrix;
  if (inst.curve != UINT32_MAX) p.bend.emplace(list.curves[inst.curve], inst.transform);
  return p;
}

// Per-instance working set, reused across the instances a task handles.
struct Scratch {
  std::vector<Vector3d> world;    // asset vertices in world space
  std::vector<Matrix3d> turn;     // bent instances: how each vertex's normal turns
  std::vector<uint32_t> remap;    // asset vertex -> output vertex within the instance
  std::vector<uint8_t> keepTri;   // triangle survives the area test
};

struct Counts {
  uint32_t vertices = 0, triangles = 0;
};

// Transforms the asset's positions and decides which triangles and vertices survive.
Counts classify(const Mesh& asset, const Placement& p, Scratch& s) {
  const size_t nv = asset.vertexCount(), nt = asset.triangleCount();
  s.world.resize(nv);
  for (size_t v = 0; v < nv; ++v) {
    const Vector3d q(asset.positions[3 * v], asset.positions[3 * v + 1], asset.positions[3 * v + 2]);
    s.world[v] = p.M.block<3, 3>(0, 0) * q + p.M.block<3, 1>(0, 3);
  }
  if (p.bend) {
    s.turn.resize(nv);
    for (size_t v = 0; v < nv; ++v) {
      const marching::BentPoint b = p.bend->atRigid(s.world[v]);
      s.world[v] = b.position;
      s.turn[v] = b.rotation;
    }
  }
  s.remap.assign(nv, kUnused);
  s.keepTri.assign(nt, 0);
  Counts c;
  for (size_t t = 0; t < nt; ++t) {
    const uint32_t* tri = &asset.indices[3 * t];
    const Vector3d& a = s.world[tri[0]];
    const double area = 0.5 * (s.world[tri[1]] - a).cross(s.world[tri[2]] - a).norm();
    if (!(area >= kMinTriangleArea)) continue;  // also drops NaN areas
    s.keepTri[t] = 1;
    ++c.triangles;
    for (int k = 0; k < 3; ++k) s.remap[tri[k]] = 0;
  }
  // Number the surviving vertices in asset order, so the output keeps the asset's layout.
  for (uint32_t& r : s.remap)
    if (r != kUnused) r = c.vertices++;
  return c;
}

// Asset mesh of an instance, or nullptr when the binding is missing.
const Mesh* assetOf(const Instance& inst, const AssetLibrary& library, const std::vector<int>& meshOf) {
  if (inst.asset >= meshOf.size() || meshOf[inst.asset] < 0) return nullptr;
  return &library.mesh(meshOf[inst.asset]);
}

std::vector<Counts> countAll(const InstanceList& list, const AssetLibrary& library,
                             const std::vector<int>& meshOf) {
  std::vector<Counts> counts(list.instances.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, list.instances.size()),
                    [&](const tbb::blocked_range<size_t>& r) {
                      Scratch s;
                      for (size_t i = r.begin(); i != r.end(); ++i) {
                        const Instance& inst = list.instances[i];
                        if (const Mesh* m = assetOf(inst, library, meshOf))
                          counts[i] = classify(*m, placementOf(inst, list), s);
                      }
                    });
  return counts;
}

void emit(const Mesh& asset, const Instance& inst, const Placement& p, const Scratch& s,
          size_t firstVertex, size_t firstTriangle, Mesh& out) {
  for (size_t v = 0; v < s.remap.size(); ++v) {
    if (s.remap[v] == kUnused) continue;
    const size_t o = 3 * (firstVertex + s.remap[v]);
    const bool hasNormals = asset.normals.size() == asset.positions.size();
    const Vector3d n0 = hasNormals ? Vector3d(asset.normals[3 * v], asset.normals[3 * v + 1],
                                              asset.normals[3 * v + 2])
                                   : Vector3d::Zero();
    Vector3d n = p.normalMatrix * n0;
    if (p.bend) n = s.turn[v] * n;
    const double len = n.norm();
    n = len > 0 ? Vector3d(n / len) : Vector3d(0, 0, 1);
    for (int d = 0; d < 3; ++d) {
      out.positions[o + d] = float(s.world[v][d]);
      out.normals[o + d] = float(n[d]);
      out.colors[o + d] = inst.color[d];
    }
    // Texture coordinates pass through unchanged; (0, 0) for an asset without them.
    if (!out.texcoords.empty()) {
      const size_t ot = 2 * (firstVertex + s.remap[v]);
      const bool has = asset.hasTexcoords();
      for (int d = 0; d < 2; ++d) out.texcoords[ot + d] = has ? asset.texcoords[2 * v + d] : 0.0f;
    }
  }
  size_t t = firstTriangle;
  for (size_t a = 0; a < s.keepTri.size(); ++a) {
    if (!s.keepTri[a]) continue;
    const uint32_t* tri = &asset.indices[3 * a];
    const uint32_t base = uint32_t(firstVertex);
    out.indices[3 * t] = base + s.remap[tri[0]];
    out.indices[3 * t + 1] = base + s.remap[tri[p.flip ? 2 : 1]];
    out.indices[3 * t + 2] = base + s.remap[tri[p.flip ? 1 : 2]];
    ++t;
  }
}

// A curve index that names no curve is the engine's bug, said before any work starts.
void checkCurves(const InstanceList& list) {
  for (size_t i = 0; i < list.instances.size(); ++i) {
    const uint32_t c = list.instances[i].curve;
    if (c != UINT32_MAX && c >= list.curves.size())
      throw std::out_of_range("instance " + std::to_string(i) + " follows curve " + std::to_string(c) +
                              ", but the instance list has " + std::to_string(list.curves.size()) + " curves");
  }
}

}  // namespace

bool resolveAssets(const InstanceList& list, AssetLibrary& library, std::vector<int>& meshOf,
                   std::string& error) {
  meshOf.assign(list.assets.size(), -1);
  for (size_t i = 0; i < list.assets.size(); ++i) {
    meshOf[i] = library.resolve(list.assets[i], error);
    if (meshOf[i] < 0) return false;
  }
  return true;
}

Mesh assembleInstances(const InstanceList& list, const AssetLibrary& library,
                       const std::vector<int>& meshOf, const Deadline* deadline, size_t* assembled) {
  Mesh out;
  assembleInstances(list, library, meshOf, out, deadline, assembled);
  return out;
}

void assembleInstances(const InstanceList& list, const AssetLibrary& library,
                       const std::vector<int>& meshOf, Mesh& out, const Deadline* deadline,
                       size_t* assembled) {
  // Block by block, in list order: pass 1 counts each instance's output; prefix sums
  // give every instance its own output range, so pass 2 writes in parallel yet the bytes
  // depend neither on the scheduling nor on the blocks. A block is a millisecond or so of
  // work, so a deadline is noticed in time.
  constexpr size_t kBlockTriangles = 4096;
  checkCurves(list);
  const size_t n = list.instances.size();
  // Emptied, not freed: reserve below keeps a reused mesh's memory (already faulted in).
  out.positions.clear();
  out.normals.clear();
  out.colors.clear();
  out.texcoords.clear();
  out.indices.clear();
  std::vector<Counts> counts;
  std::vector<size_t> firstVertex, firstTriangle;
  // Room for every asset vertex and triangle (all but degenerate ones are kept), so the
  // arrays never move while they grow block by block.
  size_t maxVertices = 0, maxTriangles = 0;
  for (const Instance& inst : list.instances)
    if (const Mesh* m = assetOf(inst, library, meshOf)) maxVertices += m->vertexCount(), maxTriangles += m->triangleCount();
  out.positions.reserve(3 * maxVertices);
  out.normals.reserve(3 * maxVertices);
  out.colors.reserve(3 * maxVertices);
  out.indices.reserve(3 * maxTriangles);
  const bool withTexcoords =
      std::any_of(list.instances.begin(), list.instances.end(), [&](const Instance& inst) {
        const Mesh* m = assetOf(inst, library, meshOf);
        return m && m->hasTexcoords();
      });
  if (withTexcoords) out.texcoords.reserve(2 * maxVertices);
  size_t begin = 0;
  while (begin < n && !(deadline && deadline->passed())) {
    size_t end = begin, work = 0;
    while (end < n && (end == begin || work < kBlockTriangles)) {
      const Mesh* m = assetOf(list.instances[end++], library, meshOf);
      work += 1 + (m ? m->triangleCount() : 0);
    }
    const size_t k = end - begin;
    counts.assign(k, Counts{});
    tbb::parallel_for(tbb::blocked_range<size_t>(0, k), [&](const tbb::blocked_range<size_t>& r) {
      Scratch s;
      for (size_t i = r.begin(); i != r.end(); ++i) {
        const Instance& inst = list.instances[begin + i];
        if (const Mesh* m = assetOf(inst, library, meshOf)) counts[i] = classify(*m, placementOf(inst, list), s);
      }
    });
    firstVertex.assign(k + 1, out.positions.size() / 3);
    firstTriangle.assign(k + 1, out.indices.size() / 3);
    for (size_t i = 0; i < k; ++i) {
      firstVertex[i + 1] = firstVertex[i] + counts[i].vertices;
      firstTriangle[i + 1] = firstTriangle[i] + counts[i].triangles;
    }
    out.positions.resize(3 * firstVertex[k]);
    out.normals.resize(3 * firstVertex[k]);
    out.colors.resize(3 * firstVertex[k]);
    out.indices.resize(3 * firstTriangle[k]);
    if (withTexcoords) out.texcoords.resize(2 * firstVertex[k]);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, k), [&](const tbb::blocked_range<size_t>& r) {
      Scratch s;
      for (size_t i = r.begin(); i != r.end(); ++i) {
        const Instance& inst = list.instances[begin + i];
        const Mesh* m = assetOf(inst, library, meshOf);
        if (!m || counts[i].triangles == 0) continue;
        const Placement p = placementOf(inst, list);
        classify(*m, p, s);
        emit(*m, inst, p, s, firstVertex[i], firstTriangle[i], out);
      }
    });
    begin = end;
  }
  if (assembled) *assembled = begin;
}

size_t countTriangles(const InstanceList& list, const AssetLibrary& library,
                      const std::vector<int>& meshOf) {
  checkCurves(list);
  size_t total = 0;
  for (const Counts& c : countAll(list, library, meshOf)) total += c.triangles;
  return total;
}

}  // namespace fgsg::rt
