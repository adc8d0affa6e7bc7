#include "runtime/surface/load_surface.h"

#include "runtime/io/file_extension.h"
#include "runtime/io/read_input.h"
#include "runtime/io/read_mesh_file.h"
#include "runtime/surface/read_textured_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <numeric>
#include <sstream>

namespace fgsg::rt::surface {

namespace {

namespace fs = std::filesystem;

// Reads vertices and fan-triangulated polygons (and texture coordinates, where the file
// has them); false with a message when the file cannot be read at all. `polygonal` tells
// whether any polygon had more than three corners.
bool readRaw(const std::string& path, SurfaceMesh& mesh, bool& polygonal, uint64_t memoryLimit, std::string& error) {
  const std::string ext = io::lowerExtension(path);
  static const char* const kFormats[] = {".obj", ".ply", ".off", ".stl", ".gltf", ".glb", ".fbx", ".dae"};
  if (std::find(std::begin(kFormats), std::end(kFormats), ext) == std::end(kFormats)) {
    error = path + ": unknown surface format '" + (ext.empty() ? std::string("(none)") : ext) +
            "' (supported: .obj .ply .off .stl .gltf .glb .fbx .dae)";
    return false;
  }
  // Texture coordinates come through assimp; files without them stay with the readers
  // that check every count first.
  if (ext != ".off" && ext != ".stl") {
    std::string bytes;
    if (!io::readInputFile(path, "a mesh file", bytes, error)) return false;
    if (readsThroughAssimp(ext, bytes)) return readTexturedMesh(path, bytes, mesh, polygonal, error, memoryLimit);
  }
  io::MeshFileContent file;
  if (!io::readMeshFile(path, file, error)) return false;
  mesh.vertices.reserve(file.vertices.size());
  for (const auto& p : file.vertices) mesh.vertices.emplace_back(p[0], p[1], p[2]);
  polygonal = false;
  mesh.faces.reserve(file.corners.size() - 2 * file.polygonCount());
  for (size_t f = 0; f < file.polygonCount(); ++f) {
    const int* poly = file.corners.data() + file.polygonStart[f];
    const size_t n = file.cornerCount(f);
    polygonal |= n > 3;
    for (size_t k = 1; k + 1 < n; ++k) mesh.faces.push_back({poly[0], poly[k], poly[k + 1]});
  }
  return true;
}

// ---------------------------------------------------------------------------------------
// Analysis: everything validation reports and repair needs, in one pass over the
// faces around each vertex (edges are grouped at their lower-numbered end).

enum Kind {
  kBadIndex,
  kNonFinite,
  kEmpty,
  kNonManifoldEdge,
  kNonManifoldVertex,
  kDegenerate,
  kDuplicate,
  kOrientation,
  kIsolated,
  kKindCount
};
// Singular and plural nouns for the "and N more" summary.
const char* const kKindNoun[kKindCount][2] = {
    {"face with a bad vertex index", "faces with bad vertex indices"},
    {"non-finite vertex", "non-finite vertices"},
    {"empty surface", "empty surfaces"},
    {"non-manifold edge", "non-manifold edges"},
    {"non-manifold vertex", "non-manifold vertices"},
    {"degenerate face", "degenerate faces"},
    {"duplicate face", "duplicate faces"},
    {"inconsistently oriented edge", "inconsistently oriented edges"},
    {"isolated vertex", "isolated vertices"},
};

std::string fmt(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p.x(), p.y(), p.z());
  return buf;
}

// Two faces across a manifold edge; `same` when both run along it the same way.
struct FacePair {
  int f, g;
  bool same;
};

struct Analysis {
  std::vector<std::vector<std::string>> listed = std::vector<std::vector<std::string>>(kKindCount);
  std::array<size_t, kKindCount> count{};
  std::vector<uint8_t> degenerate, duplicate;  // per face
  std::vector<uint8_t> open;                   // per face: has an edge without a twin
  std::vector<uint8_t> used;                   // per vertex: some face refers to it
  std::vector<FacePair> pairs;
  bool badIndices = false;

  void add(Kind k, const std::function<std::string()>& message) {
    if (count[k]++ < kMaxListedProblems) listed[k].push_back(message());
  }
  bool ok() const {
    for (size_t c : count)
      if (c) return false;
    return true;
  }
};

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  bool unite(int a, int b) {
    a = find(a), b = find(b);
    if (a == b) return false;
    parent[a] = b;
    return true;
  }
};

bool hasRepeatedCorner(const std::array<int, 3>& t) {
  return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
}

Analysis analyse(const SurfaceMesh& m) {
  Analysis a;
  const int nv = int(m.vertices.size()), nf = int(m.faces.size());
  a.degenerate.assign(nf, 0);
  a.duplicate.assign(nf, 0);
  a.open.assign(nf, 0);
  a.used.assign(nv, 0);
  if (nf == 0) a.add(kEmpty, [] { return std::string("the surface has no faces"); });

  // Faces that take part in the topology checks: valid corners, three distinct ones.
  std::vector<uint8_t> active(nf, 1);
  for (int f = 0; f < nf; ++f) {
    const auto& t = m.faces[f];
    for (int v : t)
      if (v < 0 || v >= nv) {
        a.badIndices = true;
        active[f] = 0;
        a.add(kBadIndex, [&, f, v] {
          return "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                 ", but there are only " + std::to_string(nv) + " vertices";
        });
        break;
      }
    if (!active[f]) continue;
    for (int v : t) a.used[v] = 1;
    if (hasRepeatedCorner(t)) {
      active[f] = 0;
      a.degenerate[f] = 1;
      a.add(kDegenerate, [&, f] {
        const auto& t = m.faces[f];
        const int v = t[0] == t[1] || t[0] == t[2] ? t[0] : t[1];
        return "face " + std::to_string(f) + " uses vertex " + std::to_string(v) +
               " twice (degenerate)";
      });
    }
  }

  std::vector<uint8_t> finite(nv, 1);
  for (int v = 0; v < nv; ++v)
    if (!m.vertices[v].allFinite()) {
      finite[v] = 0;
      a.add(kNonFinite, [&, v] {
        return "vertex " + std::to_string(v) + " has a non-finite coordinate " + fmt(m.vertices[v]);
      });
    }

  for (int f = 0; f < nf; ++f) {
    if (!active[f]) continue;
    const auto& t = m.faces[f];
    if (!finite[t[0]] || !finite[t[1]] || !finite[t[2]]) continue;  // reported above
    const Vec3 &p = m.vertices[t[0]], &q = m.vertices[t[1]], &r = m.vertices[t[2]];
    const double longest =
        std::max({(q - p).squaredNorm(), (r - q).squaredNorm(), (p - r).squaredNorm()});
    const double twiceArea = (q - p).cross(r - p).norm();
    if (twiceArea <= kDegenerateFaceTolerance * longest) {
      a.degenerate[f] = 1;
      a.add(kDegenerate, [&, f] {
        const auto& t = m.faces[f];
        return "face " + std::to_string(f) + " (vertices " + std::to_string(t[0]) + ", " +
               std::to_string(t[1]) + ", " + std::to_string(t[2]) + ") near " +
               fmt(m.vertices[t[0]]) + " has zero area (degenerate)";
      });
    }
  }

  // Duplicates: the same three corners, in either orientation; the first one stays.
  {
    std::vector<std::pair<std::array<int, 3>, int>> keys;
    keys.reserve(nf);
    for (int f = 0; f < nf; ++f)
      if (active[f]) {
        auto t = m.faces[f];
        std::sort(t.begin(), t.end());
        keys.push_back({t, f});
      }
    std::sort(keys.begin(), keys.end());
    size_t runStart = 0;  // where the run of equal corners that keys[i] belongs to starts
    for (size_t i = 1; i < keys.size(); ++i) {
      if (keys[i].first != keys[runStart].first) runStart = i;
      if (i != runStart) {
        const int first = keys[runStart].second, f = keys[i].second;
        active[f] = 0;
        a.duplicate[f] = 1;
        a.add(kDuplicate, [=] {
          return "faces " + std::to_string(first) + " and " + std::to_string(f) +
                 " have the same corners (duplicate face)";
        });
      }
    }
  }

  // The faces around each vertex, as a compressed list.
  std::vector<int> start(nv + 1, 0), incident;
  for (int f = 0; f < nf; ++f)
    if (active[f])
      for (int v : m.faces[f]) ++start[v + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  incident.resize(start[nv]);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int f = 0; f < nf; ++f)
      if (active[f])
        for (int v : m.faces[f]) incident[fill[v]++] = f;
  }

  struct Spoke {  // one face at vertex v touching edge (v, w)
    int w, f;
    bool outgoing;  // the face runs v -> w
    bool operator<(const Spoke& o) const { return w != o.w ? w < o.w : f < o.f; }
  };
  std::vector<Spoke> spokes;
  for (int v = 0; v < nv; ++v) {
    const int n = start[v + 1] - start[v];
    if (n == 0) continue;
    spokes.clear();
    for (int i = start[v]; i < start[v + 1]; ++i) {
      const int f = incident[i], k = m.cornerOf(f, v);
      spokes.push_back({m.faces[f][(k + 1) % 3], f, true});
      spokes.push_back({m.faces[f][(k + 2) % 3], f, false});
    }
    std::sort(spokes.begin(), spokes.end());
    UnionFind fans(n);
    // The faces at v were listed in increasing order: a face's place is a binary search.
    auto local = [&](int f) {
      const auto first = incident.begin() + start[v];
      return int(std::lower_bound(first, incident.begin() + start[v + 1], f) - first);
    };
    int fanCount = n;
    bool onNonManifoldEdge = false;
    for (size_t i = 0; i < spokes.size();) {
      size_t j = i;
      while (j < spokes.size() && spokes[j].w == spokes[i].w) ++j;
      const int w = spokes[i].w, faces = int(j - i);
      if (faces == 1) {
        a.open[spokes[i].f] = 1;
      } else if (faces == 2) {
        if (fans.unite(local(spokes[i].f), local(spokes[i + 1].f))) --fanCount;
        const bool same = spokes[i].outgoing == spokes[i + 1].outgoing;
        if (v < w) {
          a.pairs.push_back({spokes[i].f, spokes[i + 1].f, same});
          if (same)
            a.add(kOrientation, [&, v, w, i] {
              const int from = spokes[i].outgoing ? v : w, to = spokes[i].outgoing ? w : v;
              return "faces " + std::to_string(spokes[i].f) + " and " +
                     std::to_string(spokes[i + 1].f) + " both run along edge (" +
                     std::to_string(v) + ", " + std::to_string(w) + ") from " +
                     std::to_string(from) + " to " + std::to_string(to) +
                     " (inconsistent orientation)";
            });
        }
      } else {
        onNonManifoldEdge = true;
        for (size_t s = i; s < j; ++s) a.open[spokes[s].f] = 1;
        if (v < w)
          a.add(kNonManifoldEdge, [&, v, w, i, j, faces] {
            std::string list;
            for (size_t s = i; s < j; ++s)
              list += (s > i ? ", " : "") + std::to_string(spokes[s].f);
            return "edge (" + std::to_string(v) + ", " + std::to_string(w) + ") at " +
                   fmt(m.vertices[v]) + " is shared by " + std::to_string(faces) +
                   " faces (non-manifold): faces " + list;
          });
      }
      i = j;
    }
    // Two or more fans meeting only at v: a bow-tie. A vertex on a non-manifold edge is
    // reported through the edge.
    if (fanCount > 1 && !onNonManifoldEdge)
      a.add(kNonManifoldVertex, [&, v, fanCount] {
        return "vertex " + std::to_string(v) + " at " + fmt(m.vertices[v]) + " is where " +
               std::to_string(fanCount) + " separate fans of faces meet (non-manifold vertex)";
      });
  }

  if (nf > 0)
    for (int v = 0; v < nv; ++v)
      if (!a.used[v])
        a.add(kIsolated, [&, v] {
          return "vertex " + std::to_string(v) + " at " + fmt(m.vertices[v]) +
                 " belongs to no face (isolated vertex)";
        });
  return a;
}

// The listed problems, shared fairly between kinds (so one flood does not hide the rest),
// then a line counting what was left out.
std::vector<std::string> describe(const Analysis& a) {
  std::vector<size_t> take(kKindCount, 0);
  size_t total = 0;
  for (bool more = true; more && total < kMaxListedProblems;) {
    more = false;
    for (int k = 0; k < kKindCount && total < kMaxListedProblems; ++k)
      if (take[k] < a.listed[k].size()) {
        ++take[k], ++total;
        more = true;
      }
  }
  std::vector<std::string> lines;
  size_t rest = 0;
  std::string restKinds;
  for (int k = 0; k < kKindCount; ++k) {
    for (size_t i = 0; i < take[k]; ++i) lines.push_back(a.listed[k][i]);
    const size_t left = a.count[k] - take[k];
    if (left) {
      rest += left;
      restKinds += (restKinds.empty() ? "" : ", ") + std::to_string(left) + " " +
                   kKindNoun[k][left == 1 ? 0 : 1];
    }
  }
  if (rest) lines.push_back("and " + std::to_string(rest) + " more: " + restKinds);
  return lines;
}

std::string plural(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Flips faces so neighbours agree, component by component (breadth first over manifold
// edges), then turns closed components outwards. A component that cannot agree (not
// orientable) keeps its faces as they were.
size_t reorient(SurfaceMesh& m, const Analysis& a) {
  const int nf = int(m.faces.size());
  std::vector<std::vector<std::pair<int, bool>>> adjacent(nf);
  for (const auto& p : a.pairs) {
    adjacent[p.f].push_back({p.g, p.same});
    adjacent[p.g].push_back({p.f, p.same});
  }
  std::vector<int> flip(nf, -1);
  size_t flipped = 0;
  std::vector<int> component;
  for (int root = 0; root < nf; ++root) {
    if (flip[root] >= 0) continue;
    component.assign(1, root);
    flip[root] = 0;
    bool orientable = true, closed = true;
    for (size_t i = 0; i < component.size(); ++i) {
      const int f = component[i];
      closed &= !a.open[f];
      for (auto [g, same] : adjacent[f]) {
        const int want = flip[f] ^ int(same);  // same direction: one of them must turn
        if (flip[g] < 0) {
          flip[g] = want;
          component.push_back(g);
        } else if (flip[g] != want) {
          orientable = false;
        }
      }
    }
    if (!orientable) continue;
    if (closed) {
      // Divergence theorem: the enclosed volume is positive when the faces point out.
      double volume = 0;
      for (int f : component) {
        const auto& t = m.faces[f];
        const double v = m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]]));
        volume += flip[f] ? -v : v;
      }
      if (volume < 0)
        for (int f : component) flip[f] ^= 1;
    }
    for (int f : component)
      if (flip[f]) {
        std::swap(m.faces[f][1], m.faces[f][2]);
        if (!m.textureUV.empty()) std::swap(m.textureUV[f][1], m.textureUV[f][2]);
        ++flipped;
      }
  }
  return flipped;
}

}  // namespace

std::string SurfaceRepairReport::summary() const {
  std::vector<std::string> parts;
  if (degenerateFaces)
    parts.push_back("dropped " + plural(degenerateFaces, "degenerate face", "degenerate faces"));
  if (duplicateFaces)
    parts.push_back("dropped " + plural(duplicateFaces, "duplicate face", "duplicate faces"));
  if (isolatedVertices)
    parts.push_back("dropped " + plural(isolatedVertices, "isolated vertex", "isolated vertices"));
  if (flippedFaces) parts.push_back("flipped " + plural(flippedFaces, "face", "faces"));
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : ", ") + p;
  return s;
}

bool validateSurface(const SurfaceMesh& mesh, std::vector<std::string>& problems) {
  const Analysis a = analyse(mesh);
  if (a.ok()) return true;
  const auto lines = describe(a);
  problems.insert(problems.end(), lines.begin(), lines.end());
  return false;
}

SurfaceRepairReport repairSurface(SurfaceMesh& m) {
  SurfaceRepairReport report;
  m.neighbours.clear();
  m.faceNormals.clear();
  m.faceAreas.clear();
  m.vertexNormals.clear();
  m.vertexFace.clear();
  m.boundaryVertex.clear();
  Analysis a = analyse(m);
  if (a.badIndices) return report;  // nothing here can be trusted to renumber

  // Faces without area or repeating another carry nothing a surface needs. Texture
  // coordinates, per face corner, go with their faces.
  const bool textured = m.textureUV.size() == m.faces.size();
  if (!textured) m.textureUV.clear();
  size_t kept = 0;
  for (size_t f = 0; f < m.faces.size(); ++f) {
    if (a.degenerate[f]) {
      ++report.degenerateFaces;
    } else if (a.duplicate[f]) {
      ++report.duplicateFaces;
    } else {
      if (textured) m.textureUV[kept] = m.textureUV[f];
      m.faces[kept++] = m.faces[f];
    }
  }
  m.faces.resize(kept);
  if (textured) m.textureUV.resize(kept);
  if (report.degenerateFaces || report.duplicateFaces) a = analyse(m);

  report.flippedFaces = reorient(m, a);

  // Vertices no face uses (some only just now) go; the rest keep their order.
  std::vector<int> renumber(m.vertices.size(), -1);
  std::vector<uint8_t> used(m.vertices.size(), 0);
  for (const auto& t : m.faces)
    for (int v : t) used[v] = 1;
  int next = 0;
  for (size_t v = 0; v < m.vertices.size(); ++v)
    if (used[v]) {
      renumber[v] = next;
      m.vertices[next++] = m.vertices[v];
    }
  report.isolatedVertices = m.vertices.size() - size_t(next);
  m.vertices.resize(next);
  for (auto& t : m.faces)
    for (int& v : t) v = renumber[v];
  return report;
}

bool loadSurface(const std::string& path, SurfaceMesh& out, std::string& error,
                 const SurfaceLoadOptions& options, SurfaceRepairReport* repaired) {
  out = SurfaceMesh{};
  if (repaired) *repaired = {};
  SurfaceMesh mesh;
  bool polygonal = false;
  if (!readRaw(path, mesh, polygonal, options.maxMemoryBytes, error)) return false;
  if (options.repair) {
    const SurfaceRepairReport report = repairSurface(mesh);
    if (repaired) *repaired = report;
  }
  const Analysis a = analyse(mesh);
  if (!a.ok()) {
    error.clear();
    for (const auto& line : describe(a)) error += path + ": " + line + "\n";
    if (polygonal)
      error += path + ": (faces are numbered after splitting polygons into triangles)\n";
    if (!options.repair) {
      SurfaceMesh trial = mesh;
      const SurfaceRepairReport would = repairSurface(trial);
      if (would.any() && analyse(trial).ok())
        error +=
            path + ": hint: --repair-surface fixes this (a trial repair " + would.summary() + ")\n";
    }
    if (a.count[kNonManifoldEdge] || a.count[kNonManifoldVertex])
      error += path +
               ": non-manifold geometry is never repaired automatically: fix it in a "
               "modelling tool\n";
    error.pop_back();
    return false;
  }
  out = std::move(mesh);
  out.buildTopology();
  return true;
}

}  // namespace fgsg::rt::surface
