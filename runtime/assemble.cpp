#include "runtime/assemble.h"

#include "runtime/marching/curve_bend.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace fgsg::rt {

namespace {

using Eigen::Matrix3d;
using Eigen::Matrix4d;
using Eigen::Vector3d;

constexpr uint32_t kUnused = UINT32_MAX;

// How one instance maps its asset into the world.
struct Placement {
  Matrix3d A;             // linear part of the instance transform
  Vector3d t;             // its translation
  Matrix3d normalMatrix;  // cofactor of A, sign-fixed for mirrors
  bool flip = false;      // a mirroring transform: reverse winding to keep it outward
  // A smooth terminal (Instance::curve): bent along its curve after the transform.
  std::optional<marching::CurveBend> bend;
};

Placement placementOf(const Instance& inst, const InstanceList& list) {
  Placement p;
  const Eigen::Map<const Matrix4d> M(inst.transform.data());  // column-major like Eigen
  p.A = M.block<3, 3>(0, 0);
  p.t = M.block<3, 1>(0, 3);
  // cof(A) = [a2 x a3, a3 x a1, a1 x a2] satisfies (A u) x (A v) = cof(A) (u x v): it maps a
  // normal to the transformed surface's normal even when A is singular (a flattened box),
  // where the usual inverse transpose does not exist.
  const Vector3d a1 = p.A.col(0), a2 = p.A.col(1), a3 = p.A.col(2);
  p.normalMatrix.col(0) = a2.cross(a3);
  p.normalMatrix.col(1) = a3.cross(a1);
  p.normalMatrix.col(2) = a1.cross(a2);
  // A mirror (det < 0) turns outward normals and counter-clockwise winding inside out;
  // flipping both restores them. The tolerance keeps a flattened (det ~ 0) box unflipped.
  const double scale = a1.norm() * a2.norm() * a3.norm();
  p.flip = p.A.determinant() < -1e-9 * scale;
  if (p.flip) p.normalMatrix = -p.normalMatrix;
  if (inst.curve != UINT32_MAX) p.bend.emplace(list.curves[inst.curve], inst.transform);
  return p;
}

// Per-instance working set, reused across the instances a task handles.
struct Scratch {
  std::vector<Vector3d> world;         // asset vertices in world space
  std::vector<Eigen::Vector3f> normal;  // their output normals
  std::vector<uint32_t> remap;         // asset vertex -> output vertex within the instance
  std::vector<uint8_t> keepTri;        // triangle survives the area test
  std::vector<uint8_t> keepLine;       // line segment has a length
};

struct Counts {
  uint32_t vertices = 0, triangles = 0, lines = 0;
};

// The output normal: through the cofactor matrix, turned with the bend, unit length.
Eigen::Vector3f outputNormal(const Placement& p, const Vector3d& assetNormal, const Matrix3d* turn) {
  Vector3d n = p.normalMatrix * assetNormal;
  if (turn) n = *turn * n;
  const double len = n.norm();
  return (len > 0 ? Vector3d(n / len) : Vector3d(0, 0, 1)).cast<float>();
}

// Whether the triangle with this cross product has an area of kMinTriangleArea or more
// (a NaN area: no). The square root is only taken within a hair of the threshold, where
// its rounding could decide: the same answer as 0.5 |cross| >= kMinTriangleArea.
bool largeEnough(const Vector3d& cross) {
  constexpr double kSquared = 4 * kMinTriangleArea * kMinTriangleArea;  // |cross|^2 at the threshold
  const double squared = cross.squaredNorm();
  if (squared > 1.01 * kSquared) return true;
  if (!(squared > 0.99 * kSquared)) return false;
  return 0.5 * std::sqrt(squared) >= kMinTriangleArea;
}

// Transforms the asset's positions (and, `withNormals`, its normals) and decides which
// triangles and vertices survive.
Counts classify(const Mesh& asset, const Placement& p, Scratch& s, bool withNormals) {
  const size_t nv = asset.vertexCount(), nt = asset.triangleCount();
  const bool hasNormals = asset.normals.size() == asset.positions.size();
  s.world.resize(nv);
  if (withNormals) s.normal.resize(nv);
  const float* position = asset.positions.data();
  const float* normal = asset.normals.data();
  // The bend's section is evaluated once per run of vertices with the same s (a ring of
  // the bark tube: runtime/marching/curve_bend.h).
  marching::BendSection section;
  section.s = std::numeric_limits<double>::quiet_NaN();
  for (size_t v = 0; v < nv; ++v) {
    const Vector3d q(position[3 * v], position[3 * v + 1], position[3 * v + 2]);
    s.world[v] = p.A * q + p.t;
    const Matrix3d* turn = nullptr;
    if (p.bend) {
      const double along = p.bend->along(q);
      if (!(along == section.s)) section = p.bend->section(along);
      s.world[v] = p.bend->place(section, s.world[v]).position;
      turn = &section.rotation;
    }
    if (withNormals) {
      const Vector3d n0 = hasNormals ? Vector3d(normal[3 * v], normal[3 * v + 1], normal[3 * v + 2]) : Vector3d::Zero();
      s.normal[v] = outputNormal(p, n0, turn);
    }
  }
  s.remap.assign(nv, kUnused);
  s.keepTri.assign(nt, 0);
  Counts c;
  for (size_t t = 0; t < nt; ++t) {
    const uint32_t* tri = &asset.indices[3 * t];
    const Vector3d& a = s.world[tri[0]];
    if (!largeEnough((s.world[tri[1]] - a).cross(s.world[tri[2]] - a))) continue;
    s.keepTri[t] = 1;
    ++c.triangles;
    for (int k = 0; k < 3; ++k) s.remap[tri[k]] = 0;
  }
  // Line segments survive with a length (a NaN one: no).
  const size_t nl = asset.lineCount();
  s.keepLine.assign(nl, 0);
  for (size_t l = 0; l < nl; ++l) {
    const uint32_t* ends = &asset.lines[2 * l];
    if (!((s.world[ends[1]] - s.world[ends[0]]).squaredNorm() > 0)) continue;
    s.keepLine[l] = 1;
    ++c.lines;
    s.remap[ends[0]] = s.remap[ends[1]] = 0;
  }
  // Number the surviving vertices in asset order, so the output keeps the asset's layout.
  for (uint32_t& r : s.remap)
    if (r != kUnused) r = c.vertices++;
  return c;
}

// The mesh an instance draws (its own geometry, or its asset), or nullptr when the
// binding is missing.
const Mesh* assetOf(const Instance& inst, const InstanceList& list, const AssetLibrary& library,
                    const std::vector<int>& meshOf) {
  if (inst.geometry != UINT32_MAX) return &list.geometries.at(inst.geometry);
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
                        if (const Mesh* m = assetOf(inst, list, library, meshOf))
                          counts[i] = classify(*m, placementOf(inst, list), s, false);
                      }
                    });
  return counts;
}

// A block's output before its place in the mesh is known: each instance writes what
// survives into a slot with room for all of its asset, at slotVertex / slotTriangle
// (indices counted from the instance's first vertex), and is then copied into place.
// Bending a vertex costs far more than copying it: this way each is bent once.
struct Staging {
  std::vector<float> positions, normals, colors, texcoords;
  std::vector<uint32_t> indices, lines;
  std::vector<size_t> slotVertex, slotTriangle, slotLine;  // per instance of the block, and the end
};

// Writes an instance's surviving vertices and triangles into its staging slot.
void emit(const Mesh& asset, const Instance& inst, const Placement& p, const Scratch& s, size_t slot,
          Staging& st) {
  const size_t vertex0 = st.slotVertex[slot];
  float* position = st.positions.data() + 3 * vertex0;
  float* normal = st.normals.data() + 3 * vertex0;
  float* color = st.colors.data() + 3 * vertex0;
  // Texture coordinates pass through unchanged; (0, 0) for an asset without them.
  float* texcoord = st.texcoords.empty() ? nullptr : st.texcoords.data() + 2 * vertex0;
  const bool hasTexcoords = asset.hasTexcoords();
  for (size_t v = 0; v < s.remap.size(); ++v) {
    const uint32_t o = s.remap[v];
    if (o == kUnused) continue;
    for (int d = 0; d < 3; ++d) {
      position[3 * o + d] = float(s.world[v][d]);
      normal[3 * o + d] = s.normal[v][d];
      color[3 * o + d] = inst.color[d];
    }
    if (texcoord)
      for (int d = 0; d < 2; ++d) texcoord[2 * o + d] = hasTexcoords ? asset.texcoords[2 * v + d] : 0.0f;
  }
  uint32_t* index = st.indices.data() + 3 * st.slotTriangle[slot];
  for (size_t a = 0; a < s.keepTri.size(); ++a) {
    if (!s.keepTri[a]) continue;
    const uint32_t* tri = &asset.indices[3 * a];
    *index++ = s.remap[tri[0]];
    *index++ = s.remap[tri[p.flip ? 2 : 1]];
    *index++ = s.remap[tri[p.flip ? 1 : 2]];
  }
  uint32_t* line = st.lines.data() + 2 * st.slotLine[slot];
  for (size_t l = 0; l < s.keepLine.size(); ++l) {
    if (!s.keepLine[l]) continue;
    *line++ = s.remap[asset.lines[2 * l]];
    *line++ = s.remap[asset.lines[2 * l + 1]];
  }
}

// Copies an instance's staged output to its place in the mesh.
void place(const Staging& st, size_t slot, Counts c, size_t firstVertex, size_t firstTriangle, size_t firstLine,
           Mesh& out) {
  if (c.vertices == 0) return;  // nothing survived (and the slot may be past the end)
  const size_t v = st.slotVertex[slot], t = st.slotTriangle[slot], l = st.slotLine[slot];
  std::copy_n(&st.positions[3 * v], 3 * c.vertices, &out.positions[3 * firstVertex]);
  std::copy_n(&st.normals[3 * v], 3 * c.vertices, &out.normals[3 * firstVertex]);
  std::copy_n(&st.colors[3 * v], 3 * c.vertices, &out.colors[3 * firstVertex]);
  if (!out.texcoords.empty()) std::copy_n(&st.texcoords[2 * v], 2 * c.vertices, &out.texcoords[2 * firstVertex]);
  const uint32_t base = uint32_t(firstVertex);
  for (size_t k = 0; k < 3 * size_t(c.triangles); ++k) out.indices[3 * firstTriangle + k] = base + st.indices[3 * t + k];
  for (size_t k = 0; k < 2 * size_t(c.lines); ++k) out.lines[2 * firstLine + k] = base + st.lines[2 * l + k];
}

// The output's images: the instance list's (Texture), then those of drawn meshes with
// images of their own (an OBJ asset's materials), each path once; per such mesh, its
// images' numbers in the output.
struct OutputImages {
  std::vector<std::string> paths;
  std::unordered_map<const Mesh*, std::vector<int32_t>> ofMesh;
};

OutputImages outputImages(const InstanceList& list, const AssetLibrary& library, const std::vector<int>& meshOf) {
  OutputImages images;
  images.paths = list.textures;
  std::unordered_map<std::string, int32_t> number;
  for (size_t t = 0; t < images.paths.size(); ++t) number.emplace(images.paths[t], int32_t(t));
  for (const Instance& inst : list.instances) {
    const Mesh* m = assetOf(inst, list, library, meshOf);
    if (!m || !m->textured() || images.ofMesh.count(m)) continue;
    std::vector<int32_t>& own = images.ofMesh[m];
    for (const std::string& path : m->textures) {
      const auto [it, added] = number.emplace(path, int32_t(images.paths.size()));
      if (added) images.paths.push_back(path);
      own.push_back(it->second);
    }
  }
  return images;
}

// Starts a texture run wherever an instance's triangles draw another image than those
// before them (the block's instances from `begin`, at firstTriangle). A mesh with images
// of its own draws them on its textured triangles (counted again, as they survived) and
// the instance's Texture on the rest.
void addTextureRuns(const InstanceList& list, const AssetLibrary& library, const std::vector<int>& meshOf,
                    const OutputImages& images, size_t begin, const std::vector<Counts>& counts,
                    const std::vector<size_t>& firstTriangle, Mesh& out) {
  Scratch s;
  for (size_t i = 0; i < counts.size(); ++i) {
    if (counts[i].triangles == 0) continue;
    const Instance& inst = list.instances[begin + i];
    const int32_t image = inst.texture == UINT32_MAX ? -1 : int32_t(inst.texture);
    const Mesh* m = assetOf(inst, list, library, meshOf);
    if (!m->textured()) {
      out.addTextureRun(firstTriangle[i], image);
      continue;
    }
    classify(*m, placementOf(inst, list), s, false);
    const std::vector<int32_t>& own = images.ofMesh.at(m);
    size_t at = firstTriangle[i];
    for (size_t r = 0; r < m->textureRuns.size(); ++r) {
      size_t kept = 0;
      for (size_t t = m->textureRuns[r].firstTriangle; t < m->runEnd(r); ++t) kept += s.keepTri[t];
      if (kept == 0) continue;
      const int32_t texture = m->textureRuns[r].texture;
      out.addTextureRun(at, texture >= 0 ? own[size_t(texture)] : image);
      at += kept;
    }
  }
}

// Lists only the images some run draws (their instances may all have been culled or
// flattened away), renumbering the runs: every image a writer embeds is used.
void keepUsedTextures(Mesh& out) {
  std::vector<int32_t> renumbered(out.textures.size(), -1);
  std::vector<std::string> used;
  for (TextureRun& run : out.textureRuns) {
    if (run.texture < 0) continue;
    int32_t& to = renumbered[size_t(run.texture)];
    if (to < 0) to = int32_t(used.size()), used.push_back(out.textures[size_t(run.texture)]);
    run.texture = to;
  }
  out.textures = std::move(used);
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
    if (list.assets[i] == kOwnGeometryAsset) continue;  // Instance::geometry draws these
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
  // Block by block, in list order: pass 1 builds each instance's output in a staging
  // slot of its own; prefix sums over what survived give every instance its output range,
  // so pass 2 copies in parallel yet the bytes depend neither on the scheduling nor on
  // the blocks. A block is a millisecond or so of work, so a deadline is noticed in time.
  constexpr size_t kBlockTriangles = 32768;
  checkCurves(list);
  const size_t n = list.instances.size();
  // Emptied, not freed: reserve below keeps a reused mesh's memory (already faulted in).
  out.positions.clear();
  out.normals.clear();
  out.colors.clear();
  out.texcoords.clear();
  out.indices.clear();
  out.lines.clear();
  out.textures.clear();
  out.textureRuns.clear();
  std::vector<Counts> counts;
  std::vector<size_t> firstVertex, firstTriangle, firstLine;
  // Room for every asset vertex and triangle (all but degenerate ones are kept), so the
  // arrays never move while they grow block by block.
  // In the same pass: whether any drawn mesh has texture coordinates, and whether any
  // triangle draws an image (a Texture, or a mesh's own).
  size_t maxVertices = 0, maxTriangles = 0, maxLines = 0;
  bool withTexcoords = false, withTextures = false;
  for (const Instance& inst : list.instances) {
    withTextures |= inst.texture != UINT32_MAX;
    const Mesh* m = assetOf(inst, list, library, meshOf);
    if (!m) continue;
    maxVertices += m->vertexCount(), maxTriangles += m->triangleCount(), maxLines += m->lineCount();
    withTexcoords |= m->hasTexcoords();
    withTextures |= m->textured();
  }
  out.positions.reserve(3 * maxVertices);
  out.normals.reserve(3 * maxVertices);
  out.colors.reserve(3 * maxVertices);
  out.indices.reserve(3 * maxTriangles);
  out.lines.reserve(2 * maxLines);
  if (withTexcoords) out.texcoords.reserve(2 * maxVertices);
  OutputImages images;
  if (withTextures) images = outputImages(list, library, meshOf), out.textures = images.paths;
  Staging st;
  size_t begin = 0;
  while (begin < n && !(deadline && deadline->passed())) {
    // The block, and each instance's staging slot: room for its whole asset.
    size_t end = begin, work = 0;
    st.slotVertex.assign(1, 0);
    st.slotTriangle.assign(1, 0);
    st.slotLine.assign(1, 0);
    while (end < n && (end == begin || work < kBlockTriangles)) {
      const Mesh* m = assetOf(list.instances[end++], list, library, meshOf);
      work += 1 + (m ? m->triangleCount() + m->lineCount() : 0);
      st.slotVertex.push_back(st.slotVertex.back() + (m ? m->vertexCount() : 0));
      st.slotTriangle.push_back(st.slotTriangle.back() + (m ? m->triangleCount() : 0));
      st.slotLine.push_back(st.slotLine.back() + (m ? m->lineCount() : 0));
    }
    const size_t k = end - begin;
    st.positions.resize(3 * st.slotVertex[k]);
    st.normals.resize(3 * st.slotVertex[k]);
    st.colors.resize(3 * st.slotVertex[k]);
    if (withTexcoords) st.texcoords.resize(2 * st.slotVertex[k]);
    st.indices.resize(3 * st.slotTriangle[k]);
    st.lines.resize(2 * st.slotLine[k]);
    counts.assign(k, Counts{});
    tbb::parallel_for(tbb::blocked_range<size_t>(0, k), [&](const tbb::blocked_range<size_t>& r) {
      Scratch s;
      for (size_t i = r.begin(); i != r.end(); ++i) {
        const Instance& inst = list.instances[begin + i];
        const Mesh* m = assetOf(inst, list, library, meshOf);
        if (!m) continue;
        const Placement p = placementOf(inst, list);
        counts[i] = classify(*m, p, s, true);
        emit(*m, inst, p, s, i, st);
      }
    });
    firstVertex.assign(k + 1, out.positions.size() / 3);
    firstTriangle.assign(k + 1, out.indices.size() / 3);
    firstLine.assign(k + 1, out.lines.size() / 2);
    for (size_t i = 0; i < k; ++i) {
      firstVertex[i + 1] = firstVertex[i] + counts[i].vertices;
      firstTriangle[i + 1] = firstTriangle[i] + counts[i].triangles;
      firstLine[i + 1] = firstLine[i] + counts[i].lines;
    }
    out.positions.resize(3 * firstVertex[k]);
    out.normals.resize(3 * firstVertex[k]);
    out.colors.resize(3 * firstVertex[k]);
    out.indices.resize(3 * firstTriangle[k]);
    out.lines.resize(2 * firstLine[k]);
    if (withTexcoords) out.texcoords.resize(2 * firstVertex[k]);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, k), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i)
        place(st, i, counts[i], firstVertex[i], firstTriangle[i], firstLine[i], out);
    });
    if (withTextures) addTextureRuns(list, library, meshOf, images, begin, counts, firstTriangle, out);
    begin = end;
  }
  keepUsedTextures(out);
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
