// Triangulates a shape's geometry into world-space triangles for instancing and export.
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fgsg::rt::cga {
namespace {

// Relative to the square of the polygon's extent: smaller signed areas count as zero.
constexpr double kDegenerateTol = 1e-12;

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

}  // namespace

void earClip(const Vec3* pts, std::size_t count, std::vector<uint32_t>& tris) {
  const Vec3 n = newellNormal(pts, count);
  if (count < 3 || n.norm() == 0.0) return;
  const Vec3 w = n.normalized();
  const Vec3 u = w.unitOrthogonal();
  const Vec3 v = w.cross(u);  // u x v = w: counter-clockwise about w is counter-clockwise in 2D
  // The working lists, kept per thread: a city's every leaf face is clipped here, and
  // allocating them anew each time was a tenth of deriving it.
  thread_local std::vector<Vec2> q;
  thread_local std::vector<uint32_t> idx;
  q.clear();
  for (std::size_t i = 0; i < count; ++i) q.emplace_back(pts[i].dot(u), pts[i].dot(v));
  Vec2 lo = q[0], hi = q[0];
  for (const Vec2& p : q) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double eps = kDegenerateTol * (hi - lo).squaredNorm();

  auto coincide = [&](uint32_t i, uint32_t j) { return (q[i] - q[j]).squaredNorm() <= eps; };
  // Another vertex inside or on the candidate triangle (the first found), or kNone.
  constexpr uint32_t kNone = UINT32_MAX;
  auto blockerOf = [&](const std::vector<uint32_t>& idx, uint32_t a, uint32_t b, uint32_t c) {
    for (uint32_t j : idx) {
      if (coincide(j, a) || coincide(j, b) || coincide(j, c)) continue;
      if (cross(q[a], q[b], q[j]) >= -eps && cross(q[b], q[c], q[j]) >= -eps &&
          cross(q[c], q[a], q[j]) >= -eps)
        return j;
    }
    return kNone;
  };
  idx.resize(count);
  std::iota(idx.begin(), idx.end(), 0u);
  // A quad whose first corner is an ear with no vertex inside (a facade piece: most of a
  // city's leaves): the loop below would clip that ear and stop at the last triangle, so
  // the same two triangles are written without its bookkeeping. A triangle needs none.
  if (count == 4 && cross(q[3], q[0], q[1]) > eps && blockerOf(idx, 3, 0, 1) == kNone) {
    tris.insert(tris.end(), {3u, 0u, 1u});
    if (cross(q[1], q[2], q[3]) > eps) tris.insert(tris.end(), {1u, 2u, 3u});
    return;
  }
  if (count == 3) {
    if (cross(q[0], q[1], q[2]) > eps) tris.insert(tris.end(), {0u, 1u, 2u});
    return;
  }
  // Each pass clips the first ear from the start of the list. A corner that was no ear
  // stays none while its neighbours and the vertex found inside its triangle remain
  // (vertices only go), so that vertex is remembered and the corner passed over at the
  // cost of a look-up: without it a pass re-tested every corner before the ear against
  // every vertex, and a comb-shaped lot's 2 000-corner roof took a minute.
  thread_local std::vector<uint32_t> blocker, blockedA, blockedC;
  thread_local std::vector<uint8_t> alive;
  blocker.assign(count, kNone);
  blockedA.assign(count, kNone);
  blockedC.assign(count, kNone);
  alive.assign(count, 1);
  auto drop = [&](std::size_t k) {
    alive[idx[k]] = 0;
    idx.erase(idx.begin() + k);
  };
  while (idx.size() > 3) {
    const std::size_t m = idx.size();
    bool clipped = false;
    for (std::size_t k = 0; k < m && !clipped; ++k) {
      const uint32_t a = idx[(k + m - 1) % m], b = idx[k], c = idx[(k + 1) % m];
      const double cr = cross(q[a], q[b], q[c]);
      if (std::abs(cr) <= eps) {
        // A collinear vertex or the tip of a zero-width spike: dropping it loses no area.
        drop(k);
        clipped = true;
      } else if (cr > 0) {
        if (blocker[b] != kNone && alive[blocker[b]] && blockedA[b] == a && blockedC[b] == c) continue;
        const uint32_t j = blockerOf(idx, a, b, c);
        if (j != kNone) {
          blocker[b] = j, blockedA[b] = a, blockedC[b] = c;
          continue;
        }
        tris.insert(tris.end(), {a, b, c});
        drop(k);
        clipped = true;
      }
    }
    if (!clipped) {
      // Only a self-touching polygon has no ear: cut at the first vertex to terminate.
      tris.insert(tris.end(), {idx[m - 1], idx[0], idx[1]});
      drop(0);
    }
  }
  if (cross(q[idx[0]], q[idx[1]], q[idx[2]]) > eps)
    tris.insert(tris.end(), {idx[0], idx[1], idx[2]});
}

namespace {

void appendFace(const Polygon3& world, std::vector<float>& positions,
                std::vector<unsigned>& indices) {
  std::vector<uint32_t> tris;
  earClip(world, tris);
  if (tris.empty()) return;
  const auto base = static_cast<unsigned>(positions.size() / 3);
  for (const Vec3& p : world)
    positions.insert(positions.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                       static_cast<float>(p.z())});
  for (uint32_t i : tris) indices.push_back(base + i);
}

}  // namespace

// Each face gets its own vertices (flat shading). A box gives 12 triangles; faces with no
// area are skipped, so a box with one zero size (a facade wall, a footprint) gives the 4
// triangles of its two opposite faces and a box with two zero sizes gives none. Polygons
// and polyhedron faces are ear-clipped; an edge has no triangles.
void triangulate(const Scope& scope, const GeomRef& geom, const GeometryArena& arena,
                 std::vector<float>& positions, std::vector<unsigned>& indices) {
  if (geom.kind == GeomKind::Edge) return;
  auto toWorld = [&](const Vec3& n) { return scope.toWorld(scope.S.cwiseProduct(n)); };
  const std::vector<Polygon3> faces =
      geom.kind == GeomKind::Box ? unitBoxFaces() : loadGeometry(arena, geom).faces;
  Polygon3 world;
  for (const Polygon3& f : faces) {
    world.clear();
    for (const Vec3& p : f) world.push_back(toWorld(p));
    appendFace(world, positions, indices);
  }
}

}  // namespace fgsg::rt::cga
