#include "runtime/evolve/offset_surface.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_3/Point_3_Segment_3.h>
#include <CGAL/Intersections_3/Point_3_Triangle_3.h>
#include <CGAL/Intersections_3/Segment_3_Segment_3.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>

namespace fgsg::rt::evolve {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;
using Segment = K::Segment_3;
using Triangle = K::Triangle_3;

// Vertex v's offset point: the one expression both the search and the result use, so that
// the result is exactly what was searched.
Vec3 offsetPoint(const surface::SurfaceMesh& m, const std::vector<double>& height, int v) {
  return m.vertices[v] + height[v] * m.vertexNormals[v];
}

// ---------------------------------------------------------------------------------------
// Exact tests between closed triangles that may be degenerate. CGAL's triangle tests
// require proper triangles, and an offset face can collapse (its corners moved by
// different steps), so a degenerate one is tested as the segment or point it is.

struct Shape {  // a point, a segment or a proper triangle: `n` corners in `p`
  int n = 0;
  std::array<P3, 3> p;
};

Shape shapeOf(const P3& a, const P3& b) {
  if (a == b) return {1, {a, a, a}};
  return {2, {a, b, b}};
}

Shape shapeOf(const std::array<P3, 3>& t) {
  if (!CGAL::collinear(t[0], t[1], t[2])) return {3, t};
  // Collinear: the set is the segment between the two corners farthest apart.
  const double d01 = CGAL::squared_distance(t[0], t[1]), d12 = CGAL::squared_distance(t[1], t[2]),
               d02 = CGAL::squared_distance(t[0], t[2]);
  if (d01 >= d12 && d01 >= d02) return shapeOf(t[0], t[1]);
  if (d12 >= d02) return shapeOf(t[1], t[2]);
  return shapeOf(t[0], t[2]);
}

bool meets(const Shape& a, const Shape& b) {
  if (a.n > b.n) return meets(b, a);
  const Segment sa(a.p[0], a.p[1]), sb(b.p[0], b.p[1]);
  const Triangle tb(b.p[0], b.p[1], b.p[2]);
  if (a.n == 1) {
    if (b.n == 1) return a.p[0] == b.p[0];
    if (b.n == 2) return sb.has_on(a.p[0]);
    return CGAL::do_intersect(a.p[0], tb);
  }
  if (a.n == 2) return b.n == 2 ? CGAL::do_intersect(sa, sb) : CGAL::do_intersect(sa, tb);
  return CGAL::do_intersect(Triangle(a.p[0], a.p[1], a.p[2]), tb);
}

// Whether two triangles with corner identities `ia`, `ib` intersect, by the rule of the
// header: what they share by identity is contact, not intersection.
bool intersect(const std::array<P3, 3>& a, const std::array<int, 3>& ia, const std::array<P3, 3>& b,
               const std::array<int, 3>& ib) {
  int shared = 0, ka = -1, kb = -1;  // for one shared corner: its index in a and in b
  int freeA = 3, freeB = 3;           // for a shared edge: the sum of the unshared indices
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ia[i] == ib[j]) ++shared, ka = i, kb = j;
  if (shared == 0) return meets(shapeOf(a), shapeOf(b));
  if (shared == 1) {
    // They meet beyond the shared corner v exactly when the edge opposite v of one of
    // them meets the other: their common part is convex and holds v, and any segment
    // from v inside both ends, in the shorter of the two, on its opposite edge.
    const Shape edgeA = shapeOf(a[(ka + 1) % 3], a[(ka + 2) % 3]);
    const Shape edgeB = shapeOf(b[(kb + 1) % 3], b[(kb + 2) % 3]);
    return meets(edgeA, shapeOf(b)) || meets(edgeB, shapeOf(a));
  }
  if (shared == 3) return false;  // the same triangle
  // A shared edge uv: two triangles in different planes meet only along uv; in one plane
  // they overlap when their third corners lie on the same side of uv (a fold). A
  // degenerate one has no side to fold over with.
  for (int i = 0; i < 3; ++i) {
    if (std::find(ib.begin(), ib.end(), ia[i]) != ib.end()) freeA -= i;
    if (std::find(ia.begin(), ia.end(), ib[i]) != ia.end()) freeB -= i;
  }
  const P3& u = a[(freeA + 1) % 3];
  const P3& v = a[(freeA + 2) % 3];
  const P3& pa = a[freeA];
  const P3& pb = b[freeB];
  if (CGAL::collinear(u, v, pa) || CGAL::collinear(u, v, pb)) return false;
  return CGAL::coplanar(u, v, pa, pb) && CGAL::coplanar_orientation(u, v, pa, pb) == CGAL::POSITIVE;
}

// ---------------------------------------------------------------------------------------
// The triangles searched: the offset faces 0..F-1, then the mesh faces F..2F-1. A corner's
// identity is its mesh vertex index, or V + index for an offset vertex off the mesh.

struct Shell {
  const surface::SurfaceMesh& mesh;
  std::vector<P3> offsetPoints, meshPoints;
  std::vector<int> offsetId;
  int F = 0, V = 0;

  Shell(const surface::SurfaceMesh& m, const std::vector<double>& height) : mesh(m) {
    F = int(m.faces.size());
    V = int(m.vertices.size());
    offsetPoints.resize(V);
    meshPoints.resize(V);
    offsetId.resize(V);
    tbb::parallel_for(0, V, [&](int v) {
      const Vec3& x = m.vertices[v];
      const Vec3 o = offsetPoint(m, height, v);
      meshPoints[v] = P3(x.x(), x.y(), x.z());
      offsetPoints[v] = P3(o.x(), o.y(), o.z());
      offsetId[v] = height[v] == 0 ? v : V + v;
    });
  }

  bool isMesh(int t) const { return t >= F; }
  const std::array<int, 3>& face(int t) const { return mesh.faces[isMesh(t) ? t - F : t]; }
  std::array<P3, 3> corners(int t) const {
    const auto& f = face(t);
    const auto& pts = isMesh(t) ? meshPoints : offsetPoints;
    return {pts[f[0]], pts[f[1]], pts[f[2]]};
  }
  std::array<int, 3> ids(int t) const {
    const auto& f = face(t);
    if (isMesh(t)) return f;
    return {offsetId[f[0]], offsetId[f[1]], offsetId[f[2]]};
  }
};

// ---------------------------------------------------------------------------------------
// The uniform grid: each triangle's bounding box is entered in every cell it overlaps.

struct Box {
  std::array<double, 3> lo, hi;
};

constexpr int kCellBits = 21;  // per axis, packed into a 64-bit key
constexpr int64_t kMaxCells = (int64_t(1) << kCellBits) - 1;

struct CellRange {  // the cells a box overlaps, inclusive
  std::array<int64_t, 3> lo, hi;
  size_t count() const { return size_t(hi[0] - lo[0] + 1) * size_t(hi[1] - lo[1] + 1) * size_t(hi[2] - lo[2] + 1); }
};

uint64_t cellKey(int64_t i, int64_t j, int64_t k) {
  return (uint64_t(i) << (2 * kCellBits)) | (uint64_t(j) << kCellBits) | uint64_t(k);
}

template <typename F>
void forEachCell(const CellRange& r, F&& f) {
  for (int64_t i = r.lo[0]; i <= r.hi[0]; ++i)
    for (int64_t j = r.lo[1]; j <= r.hi[1]; ++j)
      for (int64_t k = r.lo[2]; k <= r.hi[2]; ++k) f(cellKey(i, j, k));
}

struct Entry {
  uint64_t key;
  int tri;
  bool operator<(const Entry& o) const { return std::tie(key, tri) < std::tie(o.key, o.tri); }
};

// The intersecting pairs among those with at least one offset face marked in `moved` (one
// flag per face; empty: all faces). A pair whose faces both stayed put keeps its outcome.
// `deadline` (read by every thread, Deadline::passed): TimeLimitReached once it passed
// (a first round on a large mesh takes a second).
std::vector<OffsetContact> search(const Shell& shell, const std::vector<uint8_t>& moved = {},
                                  const Deadline* deadline = nullptr) {
  const int T = 2 * shell.F;
  auto isMoved = [&](int t) { return !shell.isMesh(t) && (moved.empty() || moved[t]); };
  std::vector<Box> boxes(T);
  tbb::parallel_for(0, T, [&](int t) {
    const auto c = shell.corners(t);
    Box& b = boxes[t];
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = std::min({c[0][a], c[1][a], c[2][a]});
      b.hi[a] = std::max({c[0][a], c[1][a], c[2][a]});
    }
  });

  // Cells about one triangle across (the mean largest box extent), coarser if the triangles
  // would fill too many cells or the grid would need more cells per axis than a key holds.
  // The cell size changes only the speed, never the pairs found.
  std::array<double, 3> origin = boxes[0].lo, top = boxes[0].hi;
  double extent = 0;
  for (const Box& b : boxes) {
    for (int a = 0; a < 3; ++a) origin[a] = std::min(origin[a], b.lo[a]), top[a] = std::max(top[a], b.hi[a]);
    extent += std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
  }
  double span = std::max({top[0] - origin[0], top[1] - origin[1], top[2] - origin[2]});
  if (!(span > 0)) span = 1;  // every triangle in one point
  double cell = std::max(extent / T, span / double(kMaxCells - 1));
  std::vector<CellRange> ranges(T);
  for (;;) {
    tbb::parallel_for(0, T, [&](int t) {
      for (int a = 0; a < 3; ++a) {
        ranges[t].lo[a] = int64_t(std::floor((boxes[t].lo[a] - origin[a]) / cell));
        ranges[t].hi[a] = int64_t(std::floor((boxes[t].hi[a] - origin[a]) / cell));
      }
    });
    size_t total = 0;
    for (const CellRange& r : ranges) total += r.count();
    if (total <= size_t(T) * 32) break;
    cell *= 2;  // a few huge triangles: fewer, larger cells
  }

  // After the first round only cells holding a moved face matter: the others' entries
  // there are all that is kept.
  std::vector<uint64_t> movedCells;
  if (!moved.empty()) {
    for (int t = 0; t < shell.F; ++t)
      if (moved[t]) forEachCell(ranges[t], [&](uint64_t key) { movedCells.push_back(key); });
    tbb::parallel_sort(movedCells.begin(), movedCells.end());
    movedCells.erase(std::unique(movedCells.begin(), movedCells.end()), movedCells.end());
  }
  auto wanted = [&](int t, uint64_t key) {
    return moved.empty() || isMoved(t) || std::binary_search(movedCells.begin(), movedCells.end(), key);
  };
  std::vector<size_t> first(T + 1, 0);  // triangle t's entries start at first[t]
  tbb::parallel_for(0, T, [&](int t) {
    size_t n = 0;
    forEachCell(ranges[t], [&](uint64_t key) { n += wanted(t, key); });
    first[t + 1] = n;
  });
  for (int t = 0; t < T; ++t) first[t + 1] += first[t];
  std::vector<Entry> entries(first[T]);
  tbb::parallel_for(0, T, [&](int t) {
    size_t e = first[t];
    forEachCell(ranges[t], [&](uint64_t key) {
      if (wanted(t, key)) entries[e++] = {key, t};
    });
  });
  auto late = [&] { return deadline && deadline->passed(); };
  if (late()) throw TimeLimitReached{deadline->seconds()};
  tbb::parallel_sort(entries.begin(), entries.end());
  if (late()) throw TimeLimitReached{deadline->seconds()};
  std::vector<size_t> cellStart;
  for (size_t e = 0; e < entries.size(); ++e)
    if (e == 0 || entries[e].key != entries[e - 1].key) cellStart.push_back(e);
  cellStart.push_back(entries.size());

  // A pair whose boxes overlap is examined only in the cell of the lower corner of their
  // common box: the cell (max of the lower cells) both boxes reach, so exactly once.
  tbb::enumerable_thread_specific<std::vector<OffsetContact>> found;
  std::atomic<bool> stopped{false};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, cellStart.size() - 1), [&](const tbb::blocked_range<size_t>& r) {
    if (stopped.load(std::memory_order_relaxed) || late()) {
      stopped = true;
      return;
    }
    auto& out = found.local();
    for (size_t c = r.begin(); c != r.end(); ++c) {
      const size_t begin = cellStart[c], end = cellStart[c + 1];
      const uint64_t key = entries[begin].key;
      for (size_t x = begin; x < end; ++x) {
        const int s = entries[x].tri;
        if (!isMoved(s)) continue;
        // Partners: every other triangle of the cell, a moved one only once (from the
        // lower index).
        for (size_t y = begin; y < end; ++y) {
          const int t = entries[y].tri;
          if (t == s || (t < s && isMoved(t))) continue;
          const Box &bs = boxes[s], &bt = boxes[t];
          const CellRange &rs = ranges[s], &rt = ranges[t];
          if (bs.lo[0] > bt.hi[0] || bt.lo[0] > bs.hi[0] || bs.lo[1] > bt.hi[1] || bt.lo[1] > bs.hi[1] ||
              bs.lo[2] > bt.hi[2] || bt.lo[2] > bs.hi[2] ||
              cellKey(std::max(rs.lo[0], rt.lo[0]), std::max(rs.lo[1], rt.lo[1]), std::max(rs.lo[2], rt.lo[2])) != key)
            continue;
          if (!intersect(shell.corners(s), shell.ids(s), shell.corners(t), shell.ids(t))) continue;
          if (shell.isMesh(t)) out.push_back({s, t - shell.F, true});
          else out.push_back({std::min(s, t), std::max(s, t), false});
        }
      }
    }
  });
  if (stopped) throw TimeLimitReached{deadline->seconds()};
  std::vector<OffsetContact> all;
  for (auto& part : found) all.insert(all.end(), part.begin(), part.end());
  std::sort(all.begin(), all.end(), [](const OffsetContact& a, const OffsetContact& b) {
    return std::tie(a.offsetFace, a.faceIsMesh, a.face) < std::tie(b.offsetFace, b.faceIsMesh, b.face);
  });
  return all;
}

void requireTopology(const surface::SurfaceMesh& mesh, const char* who) {
  if (mesh.faces.empty()) throw std::invalid_argument(std::string(who) + ": the mesh has no faces");
  if (mesh.vertexNormals.size() != mesh.vertices.size())
    throw std::invalid_argument(std::string(who) + ": the mesh has no vertex normals (call buildTopology() first)");
}

}  // namespace

std::vector<OffsetContact> offsetContacts(const surface::SurfaceMesh& mesh, const std::vector<double>& height) {
  requireTopology(mesh, "offsetContacts");
  if (height.size() != mesh.vertices.size())
    throw std::invalid_argument("offsetContacts: " + std::to_string(height.size()) + " heights for " +
                                std::to_string(mesh.vertices.size()) + " vertices");
  for (double h : height)
    if (!(std::isfinite(h) && h >= 0))
      throw std::invalid_argument("offsetContacts: a height must be finite and not negative, got " + std::to_string(h));
  return search(Shell(mesh, height));
}

OffsetSurface offsetSurface(const surface::SurfaceMesh& mesh, const OffsetOptions& o) {
  requireTopology(mesh, "offsetSurface");
  if (!(std::isfinite(o.fraction) && o.fraction > 0))
    throw std::invalid_argument("offsetSurface: fraction must be finite and > 0, got " + std::to_string(o.fraction));
  if (!(o.shrink > 0 && o.shrink < 1))
    throw std::invalid_argument("offsetSurface: shrink must lie strictly between 0 and 1, got " +
                                std::to_string(o.shrink));
  if (o.maxRounds < 1)
    throw std::invalid_argument("offsetSurface: maxRounds must be at least 1, got " + std::to_string(o.maxRounds));

  OffsetSurface s;
  s.fullStep = o.fraction * (mesh.boundsMax - mesh.boundsMin).norm();
  if (!std::isfinite(s.fullStep))
    throw std::invalid_argument("offsetSurface: the full step (fraction x bounding-box diagonal) is not finite");
  const int V = int(mesh.vertices.size());
  s.height.assign(V, s.fullStep);

  // Heights only decrease and 0 stays, so a pair of faces lying on the mesh (every vertex
  // of its offset faces at 0) meets for good: the mesh itself intersects there. Such pairs
  // are counted as they turn up, since later rounds search only pairs with a moved face.
  size_t stuck = 0;
  std::vector<uint8_t> involved(V);
  std::vector<uint8_t> moved;  // per offset face, since the last round; empty: all (round 1)
  for (int round = 1;; ++round) {
    if (o.deadline && o.deadline->expiredNow()) throw TimeLimitReached{o.deadline->seconds()};
    const std::vector<OffsetContact> contacts = search(Shell(mesh, s.height), moved, o.deadline);
    s.rounds = round;
    if (round == 1) s.initialContacts = contacts.size();
    if (contacts.empty()) break;

    std::fill(involved.begin(), involved.end(), 0);
    for (const OffsetContact& c : contacts) {
      bool free = false;  // a vertex that can still move
      auto mark = [&](int face) {
        for (int v : mesh.faces[face]) involved[v] = 1, free = free || s.height[v] > 0;
      };
      mark(c.offsetFace);
      if (!c.faceIsMesh) mark(c.face);
      if (!free) ++stuck;
    }
    // Back to the original position and out again by the smaller step; from round
    // maxRounds on, back onto the mesh for good.
    bool anyMoved = false;
    for (int v = 0; v < V; ++v) {
      if (involved[v] && s.height[v] > 0) {
        s.height[v] = round >= o.maxRounds ? 0.0 : s.height[v] * o.shrink;
        anyMoved = true;
      } else {
        involved[v] = 0;  // from here on: the vertices that moved
      }
    }
    if (!anyMoved) break;  // every pair found is stuck
    // Only pairs with a moved face can change: the others were found apart when last
    // searched (pairs found meeting have moved, or are stuck and counted).
    moved.assign(mesh.faces.size(), 0);
    for (size_t f = 0; f < mesh.faces.size(); ++f)
      for (int v : mesh.faces[f]) moved[f] |= involved[v];
  }
  s.intersectionFree = stuck == 0;

  s.vertices.resize(V);
  for (int v = 0; v < V; ++v) {
    s.vertices[v] = offsetPoint(mesh, s.height, v);
    if (s.height[v] < s.fullStep) ++s.revertedVertices;
    if (s.height[v] == 0) ++s.zeroedVertices;
  }
  return s;
}

double heightAt(const OffsetSurface& offset, const surface::SurfaceMesh& mesh, const surface::SurfacePoint& p) {
  if (p.face < 0 || size_t(p.face) >= mesh.faces.size() || offset.height.size() != mesh.vertices.size())
    throw std::invalid_argument("heightAt: the point's face is not one of the mesh's, or the offset is of another mesh");
  const auto& f = mesh.faces[p.face];
  return p.bary[0] * offset.height[f[0]] + p.bary[1] * offset.height[f[1]] + p.bary[2] * offset.height[f[2]];
}

}  // namespace fgsg::rt::evolve
