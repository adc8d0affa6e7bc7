#include "runtime/assemble.h"

#include "runtime/marching/curve_bend.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
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

// The instances an assembly takes: the whole list, or the listed ones (in that order).
struct Selection {
  size_t count = 0;
  const uint32_t* indices = nullptr;  // null: instance k is the list's k-th
  size_t size() const { return count; }
  size_t index(size_t k) const { return indices ? indices[k] : k; }
  const Instance& instance(const InstanceList& list, size_t k) const { return list.instances[index(k)]; }
};

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

// What assembling needs to know of an asset beyond the mesh, found once per assembly
// (an instance's own geometry, drawn once, goes without): the distinct normals of its
// vertices — a bark tube's 250 vertices have 25, its rings repeat them — so each
// instance normalises those only; and whether every vertex is drawn, so an instance
// that drops nothing keeps the asset's numbering as it is.
struct AssetTraits {
  // Per vertex: its index into normals; empty when most normals differ (a smooth mesh:
  // then each vertex is normalised on its own, as without traits).
  std::vector<uint32_t> normalOf;
  std::vector<Vector3d> normals;  // distinct, in order of first use
  bool everyVertexUsed = false;   // by a triangle or a line segment
};

AssetTraits traitsOf(const Mesh& m) {
  AssetTraits t;
  const size_t nv = m.vertexCount();
  const bool hasNormals = m.normals.size() == m.positions.size();
  t.normalOf.resize(nv);
  // Normals alike bit for bit are one (keyed by their bits: -0 and NaN need no care).
  using Bits = std::array<uint32_t, 3>;
  struct BitsHash {
    size_t operator()(const Bits& b) const {
      return size_t((uint64_t(b[0]) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(b[1]) * 0xC2B2AE3D27D4EB4Full) ^ b[2]);
    }
  };
  std::unordered_map<Bits, uint32_t, BitsHash> index;
  const float zero[3] = {0, 0, 0};
  for (size_t v = 0; v < nv; ++v) {
    const float* n = hasNormals ? &m.normals[3 * v] : zero;
    Bits bits;
    std::memcpy(bits.data(), n, sizeof bits);
    const auto [it, added] = index.emplace(bits, uint32_t(t.normals.size()));
    if (added) t.normals.emplace_back(n[0], n[1], n[2]);
    t.normalOf[v] = it->second;
    if (v >= 256 && t.normals.size() > v / 2) {  // not worth it: stop hashing a large smooth mesh
      t.normalOf.clear();
      t.normals.clear();
      break;
    }
  }
  std::vector<uint8_t> used(nv, 0);
  for (uint32_t i : m.indices) used[i] = 1;
  for (uint32_t i : m.lines) used[i] = 1;
  t.everyVertexUsed = std::all_of(used.begin(), used.end(), [](uint8_t u) { return u != 0; });
  return t;
}

// Per-instance working set, reused across the instances a task handles.
struct Scratch {
  std::vector<Vector3d> world;         // asset vertices in world space
  std::vector<Vector3d> unit;          // the asset's normals placed, unit length (distinct or per vertex)
  std::vector<uint32_t> remap;         // asset vertex -> output vertex within the instance
  std::vector<uint8_t> keepTri;        // triangle survives the area test
  std::vector<uint8_t> keepLine;       // line segment has a length
  bool keepsNumbering = false;         // remap is the identity (and left unfilled)
};

struct Counts {
  uint32_t vertices = 0, triangles = 0, lines = 0;
};

// Where a run of asset vertices goes: position M q + o, and its normals turn by R.
// Rigidly (A, t, no turn), or for one bend section (CurveBend::sectionMap), so each
// vertex of a ring costs one matrix for its position and one for its normal.
struct VertexMap {
  Matrix3d M;
  Vector3d o;
  Matrix3d R;
  bool turns = false;
};

VertexMap rigidMap(const Placement& p) { return {p.A, p.t, Matrix3d::Identity(), false}; }

VertexMap sectionMap(const Placement& p, double s) {
  const marching::CurveBend::SectionMap m = p.bend->sectionMap(s);
  return {m.linear, m.offset, m.frame, true};
}

// The unit normal through the cofactor matrix of each normal in `normals` (zero where it
// vanishes; its vertices get (0, 0, 1)), for the vertex maps to turn. A bend's turn
// keeps lengths, so it is applied after: normalize(R N n) = R normalize(N n), and of
// R = frame scopeFrame^T the scope frame's part is applied here, once per instance.
// `normalAt(k)`: the k-th normal.
template <class NormalAt>
void unitNormals(const Placement& p, size_t count, NormalAt&& normalAt, std::vector<Vector3d>& unit) {
  const bool bent = p.bend && p.bend->bends();
  const Matrix3d N = bent ? Matrix3d(p.bend->scopeFrame().transpose() * p.normalMatrix) : p.normalMatrix;
  unit.resize(count);
  for (size_t k = 0; k < count; ++k) {
    const Vector3d n = N * normalAt(k);
    const double squared = n.squaredNorm();
    unit[k] = squared > 0 ? Vector3d(n / std::sqrt(squared)) : Vector3d::Zero();
  }
}

Eigen::Vector3f outputNormal(const VertexMap& map, const Vector3d& unit) {
  if (unit == Vector3d::Zero()) return Eigen::Vector3f(0, 0, 1);
  return (map.turns ? Vector3d(map.R * unit) : unit).cast<float>();
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

// Places each asset vertex in the world (s.world) and calls visit(v, map) with the map
// that placed it. The bend's section is evaluated once per run of vertices with the
// same s (a ring of the bark tube: runtime/marching/curve_bend.h).
template <class Visit>
void placeVertices(const Mesh& asset, const Placement& p, Scratch& s, Visit&& visit) {
  const size_t nv = asset.vertexCount();
  s.world.resize(nv);
  const float* position = asset.positions.data();
  const bool bent = p.bend && p.bend->bends();
  VertexMap map = rigidMap(p);
  double sectionAt = std::numeric_limits<double>::quiet_NaN();
  for (size_t v = 0; v < nv; ++v) {
    const Vector3d q(position[3 * v], position[3 * v + 1], position[3 * v + 2]);
    if (bent) {
      const double along = p.bend->along(q);
      if (!(along == sectionAt)) sectionAt = along, map = sectionMap(p, along);
    }
    s.world[v] = map.M * q + map.o;
    visit(v, map);
  }
}

// Decides from s.world which triangles and line segments survive, and numbers the
// vertices they use (s.remap, unless s.keepsNumbering). `traits`: the asset's (null for
// a shape's own geometry).
Counts survivors(const Mesh& asset, const AssetTraits* traits, Scratch& s) {
  const size_t nv = asset.vertexCount(), nt = asset.triangleCount(), nl = asset.lineCount();
  // The area test first, on its own: a tight loop with no stores but the flags.
  Counts c;
  s.keepTri.resize(nt);
  const uint32_t* index = asset.indices.data();
  const Vector3d* world = s.world.data();
  for (size_t t = 0; t < nt; ++t) {
    const Vector3d& a = world[index[3 * t]];
    const bool keep = largeEnough((world[index[3 * t + 1]] - a).cross(world[index[3 * t + 2]] - a));
    s.keepTri[t] = keep;
    c.triangles += keep;
  }
  // Line segments survive with a length (a NaN one: no).
  s.keepLine.resize(nl);
  for (size_t l = 0; l < nl; ++l) {
    const uint32_t* ends = &asset.lines[2 * l];
    const bool keep = (world[ends[1]] - world[ends[0]]).squaredNorm() > 0;
    s.keepLine[l] = keep;
    c.lines += keep;
  }
  // Nothing dropped from an asset that draws every vertex: its numbering stands.
  s.keepsNumbering = traits && traits->everyVertexUsed && c.triangles == nt && c.lines == nl;
  if (s.keepsNumbering) {
    c.vertices = uint32_t(nv);
    return c;
  }
  s.remap.assign(nv, kUnused);
  for (size_t t = 0; t < nt; ++t)
    if (s.keepTri[t])
      for (int k = 0; k < 3; ++k) s.remap[index[3 * t + k]] = 0;
  for (size_t l = 0; l < nl; ++l)
    if (s.keepLine[l]) s.remap[asset.lines[2 * l]] = s.remap[asset.lines[2 * l + 1]] = 0;
  // Number the surviving vertices in asset order, so the output keeps the asset's layout.
  for (uint32_t& r : s.remap)
    if (r != kUnused) r = c.vertices++;
  return c;
}

// What of the asset survives the instance's placement, without writing anything.
Counts classify(const Mesh& asset, const Placement& p, Scratch& s) {
  placeVertices(asset, p, s, [](size_t, const VertexMap&) {});
  return survivors(asset, nullptr, s);
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
                          counts[i] = classify(*m, placementOf(inst, list), s);
                      }
                    });
  return counts;
}

// Where a block's instances write before it is known what of them survives: each at the
// place it would have if nothing were dropped (room for all of its asset), from the
// mesh's end when the block started. Nothing is dropped almost always; where something
// is, closeUp moves the instances after it back, in order.
struct Slots {
  std::vector<size_t> vertex, triangle, line;  // per instance of the block, and the end
  size_t vertex0 = 0, triangle0 = 0, line0 = 0;  // the mesh's counts before the block
  size_t firstVertex(size_t i) const { return vertex0 + vertex[i]; }
  size_t firstTriangle(size_t i) const { return triangle0 + triangle[i]; }
  size_t firstLine(size_t i) const { return line0 + line[i]; }
};

// Writes an instance into its slot of the mesh: every vertex as it is placed, in the
// asset's numbering (what almost always survives); then, when something was dropped,
// the survivors moved together within the slot; then the triangles and line segments.
Counts placeInstance(const Mesh& asset, const AssetTraits* traits, const Instance& inst, const Placement& p,
                     Scratch& s, const Slots& slots, size_t slot, Mesh& out) {
  const size_t nv = asset.vertexCount(), vertex0 = slots.firstVertex(slot);
  // Each vertex's index into s.unit: its distinct normal's, or its own.
  const uint32_t* normalOf = traits && !traits->normalOf.empty() ? traits->normalOf.data() : nullptr;
  if (normalOf) {
    unitNormals(p, traits->normals.size(), [&](size_t k) { return traits->normals[k]; }, s.unit);
  } else {
    const float* n = asset.normals.size() == asset.positions.size() ? asset.normals.data() : nullptr;
    unitNormals(p, nv, [&](size_t v) { return n ? Vector3d(n[3 * v], n[3 * v + 1], n[3 * v + 2]) : Vector3d::Zero(); },
                s.unit);
  }
  float* position = out.positions.data() + 3 * vertex0;
  float* normal = out.normals.data() + 3 * vertex0;
  float* color = out.colors.data() + 3 * vertex0;
  // Texture coordinates pass through unchanged; (0, 0) for an asset without them.
  float* texcoord = out.texcoords.empty() ? nullptr : out.texcoords.data() + 2 * vertex0;
  const float* assetTexcoord = asset.hasTexcoords() ? asset.texcoords.data() : nullptr;
  placeVertices(asset, p, s, [&](size_t v, const VertexMap& map) {
    const Eigen::Vector3f n = outputNormal(map, s.unit[normalOf ? normalOf[v] : v]);
    for (int d = 0; d < 3; ++d) {
      position[3 * v + d] = float(s.world[v][d]);
      normal[3 * v + d] = n[d];
      color[3 * v + d] = inst.color[d];
    }
    if (texcoord)
      for (int d = 0; d < 2; ++d) texcoord[2 * v + d] = assetTexcoord ? assetTexcoord[2 * v + d] : 0.0f;
  });
  // CGA's uv sets 1..9 likewise, (0, 0) where the instance's mesh lacks the set.
  for (MeshUvSet& set : out.uvSets) {
    float* to = set.coords.data() + 2 * vertex0;
    const MeshArray<float>* from = asset.uvSet(set.set);
    for (size_t k = 0; k < 2 * nv; ++k) to[k] = from ? (*from)[k] : 0.0f;
  }
  const Counts c = survivors(asset, traits, s);
  // An asset vertex's number in the instance's output (kUnused: dropped). Renumbering
  // only ever moves a vertex back, so moving them in order overwrites none still to move.
  const bool same = s.keepsNumbering;
  const auto to = [&](uint32_t v) { return same ? v : s.remap[v]; };
  if (!same)
    for (uint32_t v = 0; v < uint32_t(nv); ++v) {
      const uint32_t o = s.remap[v];
      if (o == kUnused || o == v) continue;
      std::copy_n(position + 3 * v, 3, position + 3 * o);
      std::copy_n(normal + 3 * v, 3, normal + 3 * o);
      std::copy_n(color + 3 * v, 3, color + 3 * o);
      if (texcoord) std::copy_n(texcoord + 2 * v, 2, texcoord + 2 * o);
      for (MeshUvSet& set : out.uvSets) {
        float* t = set.coords.data() + 2 * vertex0;
        std::copy_n(t + 2 * v, 2, t + 2 * o);
      }
    }
  const uint32_t base = uint32_t(vertex0);
  uint32_t* index = out.indices.data() + 3 * slots.firstTriangle(slot);
  const int second = p.flip ? 2 : 1, third = p.flip ? 1 : 2;
  for (size_t a = 0; a < s.keepTri.size(); ++a) {
    if (!s.keepTri[a]) continue;
    const uint32_t* tri = &asset.indices[3 * a];
    *index++ = base + to(tri[0]);
    *index++ = base + to(tri[second]);
    *index++ = base + to(tri[third]);
  }
  uint32_t* line = out.lines.data() + 2 * slots.firstLine(slot);
  for (size_t l = 0; l < s.keepLine.size(); ++l) {
    if (!s.keepLine[l]) continue;
    *line++ = base + to(asset.lines[2 * l]);
    *line++ = base + to(asset.lines[2 * l + 1]);
  }
  return c;
}

// Moves each instance of the block from its slot to its place after what survived of
// the instances before it (`first*`, prefix sums of `counts`), renumbering its indices;
// in order, so no instance is overwritten before it moved. Instances before the first
// one that dropped something stay where they are.
void closeUp(const Slots& slots, const std::vector<Counts>& counts, const std::vector<size_t>& firstVertex,
             const std::vector<size_t>& firstTriangle, const std::vector<size_t>& firstLine, Mesh& out) {
  for (size_t i = 0; i < counts.size(); ++i) {
    const size_t fromVertex = slots.firstVertex(i), fromTriangle = slots.firstTriangle(i),
                 fromLine = slots.firstLine(i);
    if (fromVertex == firstVertex[i] && fromTriangle == firstTriangle[i] && fromLine == firstLine[i]) continue;
    const Counts c = counts[i];
    const auto move = [&](auto& array, int width) {
      const auto* from = array.data() + width * fromVertex;  // after the destination: a forward copy
      std::copy(from, from + width * size_t(c.vertices), array.data() + width * firstVertex[i]);
    };
    move(out.positions, 3);
    move(out.normals, 3);
    move(out.colors, 3);
    if (!out.texcoords.empty()) move(out.texcoords, 2);
    for (MeshUvSet& set : out.uvSets) move(set.coords, 2);
    const uint32_t back = uint32_t(fromVertex - firstVertex[i]);
    for (size_t k = 0; k < 3 * size_t(c.triangles); ++k)
      out.indices[3 * firstTriangle[i] + k] = out.indices[3 * fromTriangle + k] - back;
    for (size_t k = 0; k < 2 * size_t(c.lines); ++k)
      out.lines[2 * firstLine[i] + k] = out.lines[2 * fromLine + k] - back;
  }
}

// The output's images: the instance list's (Texture), then those of drawn meshes with
// images of their own (an OBJ asset's materials), each path once; per such mesh, its
// images' numbers in the output.
struct OutputImages {
  std::vector<std::string> paths;
  std::unordered_map<const Mesh*, std::vector<int32_t>> ofMesh;
};

OutputImages outputImages(const InstanceList& list, const Selection& which, const AssetLibrary& library,
                          const std::vector<int>& meshOf) {
  OutputImages images;
  images.paths = list.textures;
  std::unordered_map<std::string, int32_t> number;
  for (size_t t = 0; t < images.paths.size(); ++t) number.emplace(images.paths[t], int32_t(t));
  for (size_t k = 0; k < which.size(); ++k) {
    const Instance& inst = which.instance(list, k);
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
void addTextureRuns(const InstanceList& list, const Selection& which, const AssetLibrary& library,
                    const std::vector<int>& meshOf, const OutputImages& images, size_t begin, const std::vector<Counts>& counts,
                    const std::vector<size_t>& firstTriangle, Mesh& out) {
  Scratch s;
  for (size_t i = 0; i < counts.size(); ++i) {
    if (counts[i].triangles == 0) continue;
    const Instance& inst = which.instance(list, begin + i);
    const int32_t image = inst.texture == UINT32_MAX ? -1 : int32_t(inst.texture);
    const Mesh* m = assetOf(inst, list, library, meshOf);
    if (!m->textured()) {
      out.addTextureRun(firstTriangle[i], image);
      continue;
    }
    classify(*m, placementOf(inst, list), s);
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
void checkCurves(const InstanceList& list, const Selection& which) {
  for (size_t k = 0; k < which.size(); ++k) {
    const uint32_t c = which.instance(list, k).curve;
    if (c != UINT32_MAX && c >= list.curves.size())
      throw std::out_of_range("instance " + std::to_string(which.index(k)) + " follows curve " + std::to_string(c) +
                              ", but the instance list has " + std::to_string(list.curves.size()) + " curves");
  }
}

}  // namespace

bool assemblyBlockMayStart(const Deadline& deadline, double writeSecondsPerTriangle, size_t trianglesTaken) {
  if (deadline.passed()) return false;
  return !(writeSecondsPerTriangle > 0) || deadline.remainingSeconds() > writeSecondsPerTriangle * double(trianglesTaken);
}

const Mesh* instanceMesh(const Instance& inst, const InstanceList& list, const AssetLibrary& library,
                         const std::vector<int>& meshOf) {
  return assetOf(inst, list, library, meshOf);
}

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
                       const std::vector<int>& meshOf, const Deadline* deadline, size_t* assembled,
                       double writeSecondsPerTriangle) {
  Mesh out;
  assembleInstances(list, library, meshOf, out, deadline, assembled, writeSecondsPerTriangle);
  return out;
}

namespace {

void assemble(const InstanceList& list, const Selection& which, const AssetLibrary& library,
              const std::vector<int>& meshOf, Mesh& out, const Deadline* deadline, size_t* assembled,
              double writeSecondsPerTriangle) {
  // Block by block, in list order: each instance writes its output in parallel into a
  // slot of its own (Slots), and closeUp moves them together where something was
  // dropped, so the bytes depend neither on the scheduling nor on the blocks (of
  // kAssemblyBlockTriangles: a deadline is noticed in time).
  // A block of less work than this runs on the calling thread: a group's few pieces in
  // the scene's baked parts (runtime/output/scene.cpp) cost less than TBB's start.
  constexpr size_t kSerialTriangles = 4096;
  checkCurves(list, which);
  const size_t n = which.size();
  // Emptied, not freed: reserve below keeps a reused mesh's memory (already faulted in).
  out.positions.clear();
  out.normals.clear();
  out.colors.clear();
  out.texcoords.clear();
  out.indices.clear();
  out.lines.clear();
  out.textures.clear();
  out.textureRuns.clear();
  out.uvSets.clear();
  std::vector<Counts> counts;
  std::vector<size_t> firstVertex, firstTriangle, firstLine;
  // Room for every asset vertex and triangle (all but degenerate ones are kept), so the
  // arrays never move while they grow block by block.
  // In the same pass: whether any drawn mesh has texture coordinates, and whether any
  // triangle draws an image (a Texture, or a mesh's own).
  size_t maxVertices = 0, maxTriangles = 0, maxLines = 0;
  bool withTexcoords = false, withTextures = false;
  uint32_t uvSetsDrawn = 0;  // bit k: some drawn mesh has CGA's uv set k (1..9)
  for (size_t k = 0; k < n; ++k) {
    const Instance& inst = which.instance(list, k);
    withTextures |= inst.texture != UINT32_MAX;
    const Mesh* m = assetOf(inst, list, library, meshOf);
    if (!m) continue;
    maxVertices += m->vertexCount(), maxTriangles += m->triangleCount(), maxLines += m->lineCount();
    withTexcoords |= m->hasTexcoords();
    withTextures |= m->textured();
    for (const MeshUvSet& set : m->uvSets) uvSetsDrawn |= 1u << set.set;
  }
  out.positions.reserve(3 * maxVertices);
  out.normals.reserve(3 * maxVertices);
  out.colors.reserve(3 * maxVertices);
  out.indices.reserve(3 * maxTriangles);
  out.lines.reserve(2 * maxLines);
  if (withTexcoords) out.texcoords.reserve(2 * maxVertices);
  for (uint32_t set = 1; set < 32; ++set)
    if (uvSetsDrawn & (1u << set)) {
      out.uvSets.push_back({set, {}});
      out.uvSets.back().coords.reserve(2 * maxVertices);
    }
  OutputImages images;
  if (withTextures) images = outputImages(list, which, library, meshOf), out.textures = images.paths;
  // The traits of the assets drawn (not of every asset the list names: a scene's group
  // draws a few of them).
  std::vector<AssetTraits> traits(meshOf.size());
  std::vector<uint8_t> drawn(meshOf.size(), 0);
  for (size_t k = 0; k < n; ++k) {
    const Instance& inst = which.instance(list, k);
    if (inst.geometry == UINT32_MAX && inst.asset < meshOf.size() && meshOf[inst.asset] >= 0 && !drawn[inst.asset])
      drawn[inst.asset] = 1, traits[inst.asset] = traitsOf(library.mesh(meshOf[inst.asset]));
  }
  Slots slots;
  Scratch serialScratch;
  size_t begin = 0;
  auto timeLeft = [&] {
    return !deadline || assemblyBlockMayStart(*deadline, writeSecondsPerTriangle, out.triangleCount());
  };
  while (begin < n && timeLeft()) {
    // The block, and each instance's slot: room for its whole asset.
    size_t end = begin, work = 0;
    slots.vertex.assign(1, 0);
    slots.triangle.assign(1, 0);
    slots.line.assign(1, 0);
    while (end < n && (end == begin || work < kAssemblyBlockTriangles)) {
      const Mesh* m = assetOf(which.instance(list, end++), list, library, meshOf);
      work += 1 + (m ? m->triangleCount() + m->lineCount() : 0);
      slots.vertex.push_back(slots.vertex.back() + (m ? m->vertexCount() : 0));
      slots.triangle.push_back(slots.triangle.back() + (m ? m->triangleCount() : 0));
      slots.line.push_back(slots.line.back() + (m ? m->lineCount() : 0));
    }
    const size_t k = end - begin;
    slots.vertex0 = out.vertexCount(), slots.triangle0 = out.triangleCount(), slots.line0 = out.lineCount();
    // Within the reservation above: the arrays do not move.
    out.positions.resize(3 * slots.firstVertex(k));
    out.normals.resize(3 * slots.firstVertex(k));
    out.colors.resize(3 * slots.firstVertex(k));
    if (withTexcoords) out.texcoords.resize(2 * slots.firstVertex(k));
    for (MeshUvSet& set : out.uvSets) set.coords.resize(2 * slots.firstVertex(k));
    out.indices.resize(3 * slots.firstTriangle(k));
    out.lines.resize(2 * slots.firstLine(k));
    counts.assign(k, Counts{});
    const auto place = [&](const tbb::blocked_range<size_t>& r, Scratch& s) {
      for (size_t i = r.begin(); i != r.end(); ++i) {
        const Instance& inst = which.instance(list, begin + i);
        const Mesh* m = assetOf(inst, list, library, meshOf);
        if (!m) continue;
        const Placement p = placementOf(inst, list);
        const AssetTraits* t = inst.geometry == UINT32_MAX ? &traits[inst.asset] : nullptr;
        counts[i] = placeInstance(*m, t, inst, p, s, slots, i, out);
      }
    };
    if (work < kSerialTriangles) {
      place(tbb::blocked_range<size_t>(0, k), serialScratch);
    } else {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, k), [&](const tbb::blocked_range<size_t>& r) {
        Scratch s;
        place(r, s);
      });
    }
    firstVertex.assign(k + 1, slots.vertex0);
    firstTriangle.assign(k + 1, slots.triangle0);
    firstLine.assign(k + 1, slots.line0);
    for (size_t i = 0; i < k; ++i) {
      firstVertex[i + 1] = firstVertex[i] + counts[i].vertices;
      firstTriangle[i + 1] = firstTriangle[i] + counts[i].triangles;
      firstLine[i + 1] = firstLine[i] + counts[i].lines;
    }
    closeUp(slots, counts, firstVertex, firstTriangle, firstLine, out);
    out.positions.resize(3 * firstVertex[k]);
    out.normals.resize(3 * firstVertex[k]);
    out.colors.resize(3 * firstVertex[k]);
    out.indices.resize(3 * firstTriangle[k]);
    out.lines.resize(2 * firstLine[k]);
    if (withTexcoords) out.texcoords.resize(2 * firstVertex[k]);
    for (MeshUvSet& set : out.uvSets) set.coords.resize(2 * firstVertex[k]);
    if (withTextures) addTextureRuns(list, which, library, meshOf, images, begin, counts, firstTriangle, out);
    begin = end;
  }
  keepUsedTextures(out);
  if (assembled) *assembled = begin;
}

}  // namespace

void assembleInstances(const InstanceList& list, const AssetLibrary& library,
                       const std::vector<int>& meshOf, Mesh& out, const Deadline* deadline,
                       size_t* assembled, double writeSecondsPerTriangle) {
  assemble(list, Selection{list.instances.size(), nullptr}, library, meshOf, out, deadline, assembled,
           writeSecondsPerTriangle);
}

void assembleSelected(const InstanceList& list, const std::vector<uint32_t>& which, const AssetLibrary& library,
                      const std::vector<int>& meshOf, Mesh& out) {
  for (uint32_t i : which)
    if (i >= list.instances.size())
      throw std::out_of_range("instance " + std::to_string(i) + " of " + std::to_string(list.instances.size()));
  assemble(list, Selection{which.size(), which.data()}, library, meshOf, out, nullptr, nullptr, 0);
}

size_t countTriangles(const InstanceList& list, const AssetLibrary& library,
                      const std::vector<int>& meshOf) {
  checkCurves(list, Selection{list.instances.size(), nullptr});
  size_t total = 0;
  for (const Counts& c : countAll(list, library, meshOf)) total += c.triangles;
  return total;
}

}  // namespace fgsg::rt
