#include "runtime/synthesis/continuous/boundary_surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace fgsg::rt::synthesis::continuous {

namespace {

struct PlaneFrame {
  DVec3 b1, b2;  // b1 x b2 along the plane's normal
};

PlaneFrame frameOf(const IVec3& a) {
  const double n = std::sqrt(double(dot(a, a)));
  const DVec3 w{a[0] / n, a[1] / n, a[2] / n};
  const DVec3 h = std::abs(w[0]) < 0.6 ? DVec3{1, 0, 0} : DVec3{0, 1, 0};
  DVec3 b1{w[1] * h[2] - w[2] * h[1], w[2] * h[0] - w[0] * h[2], w[0] * h[1] - w[1] * h[0]};
  const double l = std::sqrt(b1[0] * b1[0] + b1[1] * b1[1] + b1[2] * b1[2]);
  for (auto& c : b1) c /= l;
  const DVec3 b2{w[1] * b1[2] - w[2] * b1[1], w[2] * b1[0] - w[0] * b1[2], w[0] * b1[1] - w[1] * b1[0]};
  return {b1, b2};
}

// An arrangement face on the surface: its corners (outward, counter-clockwise) and the
// plane it lies on (direction, side, offset a·x as num / den).
struct SurfaceFace {
  std::vector<int32_t> corners;
  int direction = 0;
  bool outwardAlong = false;
  int64_t offsetNum = 0, offsetDen = 1;
};

// Connected parts of the solid (faces sharing a corner), numbered in face order: per
// arrangement vertex its part, -1 for a vertex on no face.
std::vector<int32_t> partsOf(const Arrangement& A, const std::vector<SurfaceFace>& faces, uint32_t& count) {
  std::vector<int32_t> up(A.vertexCount(), -1);
  auto find = [&](int32_t a) {  // with path halving: one part can hold most faces
    while (up[size_t(a)] != a) a = up[size_t(a)] = up[size_t(up[size_t(a)])];
    return a;
  };
  for (const auto& f : faces)
    for (int32_t v : f.corners)
      if (up[size_t(v)] < 0) up[size_t(v)] = v;
  for (const auto& f : faces)
    for (size_t k = 1; k < f.corners.size(); ++k) {
      const int32_t a = find(f.corners[0]), b = find(f.corners[k]);
      if (a != b) up[size_t(b)] = a;
    }
  std::vector<int32_t> number(A.vertexCount(), -1), part(A.vertexCount(), -1);
  count = 0;
  for (const auto& f : faces) {
    int32_t& n = number[size_t(find(f.corners[0]))];
    if (n < 0) n = int32_t(count++);
  }
  for (size_t v = 0; v < A.vertexCount(); ++v)
    if (up[v] >= 0) part[v] = number[size_t(find(int32_t(v)))];
  return part;
}

// Merges touching faces of one plane and side into whole faces (see the header).
void mergeFaces(const Arrangement& A, const std::vector<SurfaceFace>& faces, const std::vector<int32_t>& partOf,
                double spacing, BoundarySurface& out) {
  // Faces of one plane and side that share an edge form a region.
  std::map<std::tuple<int, bool, int64_t, int64_t>, std::vector<size_t>> byPlane;
  for (size_t i = 0; i < faces.size(); ++i)
    byPlane[{faces[i].direction, faces[i].outwardAlong, faces[i].offsetNum, faces[i].offsetDen}].push_back(i);
  auto point = [&](int32_t v) {
    DVec3 p = A.position(size_t(v));
    for (auto& c : p) c *= spacing;
    return p;
  };
  auto emit = [&](const std::vector<int32_t>& loop, uint32_t part) {
    std::vector<DVec3> pts;
    for (int32_t v : loop) pts.push_back(point(v));
    out.faces.push_back(std::move(pts));
    out.facePart.push_back(part);
  };
  std::vector<size_t> faceUp(faces.size());  // union-find over faces, per plane's members
  struct Edge {
    int32_t from, to;
    size_t face;
    bool operator<(const Edge& o) const { return from != o.from ? from < o.from : to < o.to; }
  };
  std::vector<Edge> edges, boundary;
  std::vector<std::pair<size_t, size_t>> byRegion;  // (region root, index into boundary)
  std::vector<uint8_t> whole(faces.size(), 0);      // per region root: merged into one face
  for (const auto& [plane, members] : byPlane) {
    // Directed edges of the region's faces, sorted; an edge met both ways is inside.
    edges.clear();
    for (size_t i : members) {
      const auto& c = faces[i].corners;
      for (size_t k = 0; k < c.size(); ++k) edges.push_back({c[k], c[(k + 1) % c.size()], i});
    }
    std::sort(edges.begin(), edges.end());
    for (size_t i : members) faceUp[i] = i;
    auto findFace = [&](size_t a) {
      while (faceUp[a] != a) a = faceUp[a] = faceUp[faceUp[a]];
      return a;
    };
    boundary.clear();
    for (const Edge& e : edges) {
      const auto twin = std::lower_bound(edges.begin(), edges.end(), Edge{e.to, e.from, 0});
      if (twin != edges.end() && twin->from == e.to && twin->to == e.from) faceUp[findFace(e.face)] = findFace(twin->face);
      else boundary.push_back(e);
    }
    // Trace each region's boundary; a region whose boundary is not one simple loop
    // (a hole, corners touching) keeps its arrangement faces.
    byRegion.clear();
    for (size_t k = 0; k < boundary.size(); ++k) byRegion.push_back({findFace(boundary[k].face), k});
    std::sort(byRegion.begin(), byRegion.end());
    std::vector<Edge> bedges;
    for (size_t r = 0; r < byRegion.size();) {
      const size_t root = byRegion[r].first;
      bedges.clear();
      for (; r < byRegion.size() && byRegion[r].first == root; ++r) bedges.push_back(boundary[byRegion[r].second]);
      std::sort(bedges.begin(), bedges.end());  // by start: one successor each when simple
      bool simple = true;
      for (size_t k = 1; k < bedges.size(); ++k) simple &= bedges[k].from != bedges[k - 1].from;
      std::vector<int32_t> loop;
      if (simple) {
        int32_t at = bedges[0].from;
        do {
          loop.push_back(at);
          const auto it = std::lower_bound(bedges.begin(), bedges.end(), Edge{at, INT32_MIN, 0});
          if (it == bedges.end() || it->from != at) { simple = false; break; }
          at = it->to;
        } while (at != bedges[0].from && loop.size() <= bedges.size());
        simple &= loop.size() == bedges.size();
      }
      if (!simple) continue;
      // Drop corners on straight sides (the exact direction test on lattice vectors).
      std::vector<int32_t> corners;
      for (size_t k = 0; k < loop.size(); ++k) {
        const int32_t a = loop[(k + loop.size() - 1) % loop.size()], b = loop[k], c = loop[(k + 1) % loop.size()];
        IVec3 u{}, w{};
        for (int i = 0; i < 3; ++i) {
          u[size_t(i)] = A.num[size_t(b)][size_t(i)] * A.den[size_t(a)] - A.num[size_t(a)][size_t(i)] * A.den[size_t(b)];
          w[size_t(i)] = A.num[size_t(c)][size_t(i)] * A.den[size_t(b)] - A.num[size_t(b)][size_t(i)] * A.den[size_t(c)];
        }
        if (!isZero(canonicalDirection(cross(canonicalDirection(u), canonicalDirection(w))))) corners.push_back(b);
      }
      emit(corners, uint32_t(partOf[size_t(loop[0])]));
      whole[root] = 1;
    }
    for (size_t i : members)
      if (!whole[findFace(i)]) emit(faces[i].corners, uint32_t(partOf[size_t(faces[i].corners[0])]));
  }
}

}  // namespace

BoundarySurface boundarySurface(const Arrangement& A, const std::vector<Label>& labels,
                                const std::vector<int32_t>& labelOf, double spacing) {
  BoundarySurface out;
  Mesh& mesh = out.mesh;
  const size_t n = A.vertexCount();
  std::vector<uint32_t> used(A.edgeTo.size(), 0);  // per half-edge: planes whose face on its left is done
  std::vector<int32_t> meshIndex(n, -1);
  std::vector<PlaneFrame> frames;
  for (const IVec3& a : A.dirs) frames.push_back(frameOf(a));
  auto angle = [&](size_t e, int l) {
    const IVec3 d = A.edgeDirection(e);
    return std::atan2(dotd(d, frames[size_t(l)].b2), dotd(d, frames[size_t(l)].b1));
  };
  std::vector<int32_t> source;  // per mesh vertex: an arrangement vertex of its part
  auto vertexOut = [&](int32_t v) -> uint32_t {
    if (meshIndex[size_t(v)] < 0) {
      const DVec3 p = A.position(size_t(v));
      meshIndex[size_t(v)] = int32_t(mesh.vertexCount());
      for (double c : p) mesh.positions.push_back(float(c * spacing));
      source.push_back(v);
    }
    return uint32_t(meshIndex[size_t(v)]);
  };
  // In-plane edges of v on plane l, by angle.
  std::vector<std::pair<double, uint32_t>> ring;
  auto ringOf = [&](int32_t v, int l) {
    ring.clear();
    for (uint32_t e = A.edgeStart[size_t(v)]; e < A.edgeStart[size_t(v) + 1]; ++e)
      if (dot(A.dirs[size_t(l)], A.edgeDirection(e)) == 0) ring.push_back({angle(e, l), e});
    std::sort(ring.begin(), ring.end());
  };
  std::vector<int32_t> poly;
  std::vector<SurfaceFace> faces;
  for (size_t v = 0; v < n; ++v) {
    const Label& lab = labels[size_t(labelOf[v])];
    if (lab.dirs == 0) continue;  // empty or full: no face at v
    for (uint32_t m = lab.dirs; m; m &= m - 1) {
      const int l = __builtin_ctz(m);
      ringOf(int32_t(v), l);
      const auto corners = ring;  // ringOf is reused while tracing
      for (size_t c = 0; c < corners.size(); ++c) {
        const uint32_t start = corners[c].second;
        if ((used[start] >> l) & 1) continue;
        // The corner between this edge and the next counter-clockwise one.
        const double a0 = corners[c].first;
        double a1 = c + 1 < corners.size() ? corners[c + 1].first : corners[0].first + 2 * M_PI;
        const double mid = 0.5 * (a0 + a1);
        const PlaneFrame& f = frames[size_t(l)];
        const DVec3 r{std::cos(mid) * f.b1[0] + std::sin(mid) * f.b2[0], std::cos(mid) * f.b1[1] + std::sin(mid) * f.b2[1],
                      std::cos(mid) * f.b1[2] + std::sin(mid) * f.b2[2]};
        uint32_t signs = 0;
        bool onPlane = false;
        for (uint32_t k = lab.dirs & ~(1u << l); k; k &= k - 1) {
          const int e = __builtin_ctz(k);
          const double t = dotd(A.dirs[size_t(e)], r);
          if (std::abs(t) < 1e-9) onPlane = true;
          if (t > 0) signs |= 1u << e;
        }
        if (onPlane) continue;
        const bool above = lab.inside(signs | (1u << l)), below = lab.inside(signs);
        if (above == below) continue;
        // Trace the face counter-clockwise around +a_l: at each vertex, the edge just
        // clockwise of the one we arrived by.
        poly.clear();
        int32_t cur = int32_t(v);
        uint32_t he = start;
        for (size_t guard = 0; guard < 4096; ++guard) {
          used[he] |= 1u << l;
          poly.push_back(cur);
          const int32_t w = A.edgeTo[he];
          ringOf(w, l);
          size_t twin = ring.size();
          for (size_t k = 0; k < ring.size(); ++k)
            if (A.edgeTo[ring[k].second] == cur) twin = k;
          if (twin == ring.size()) break;
          he = ring[(twin + ring.size() - 1) % ring.size()].second;
          cur = w;
          if (he == start) break;
        }
        if (poly.size() < 3) continue;
        // Outward: from the inside across the plane.
        if (above) std::reverse(poly.begin(), poly.end());
        ++out.polygons;
        {
          SurfaceFace sf;
          sf.corners = poly;
          sf.direction = l;
          sf.outwardAlong = !above;
          // a·x is the same rational at every corner: num / den of the first.
          const int64_t num = dot(A.dirs[size_t(l)], A.num[size_t(poly[0])]), den = A.den[size_t(poly[0])];
          const int64_t g = std::gcd(std::abs(num), den);
          sf.offsetNum = g ? num / g : 0;
          sf.offsetDen = g ? den / g : 1;
          faces.push_back(std::move(sf));
        }
        if (poly.size() == 3) {
          for (int32_t p : poly) mesh.indices.push_back(vertexOut(p));
          continue;
        }
        DVec3 centre{0, 0, 0};
        for (int32_t p : poly) {
          const DVec3 q = A.position(size_t(p));
          for (int i = 0; i < 3; ++i) centre[size_t(i)] += q[size_t(i)] / double(poly.size());
        }
        const uint32_t ci = uint32_t(mesh.vertexCount());
        for (double c0 : centre) mesh.positions.push_back(float(c0 * spacing));
        source.push_back(poly[0]);
        for (size_t k = 0; k < poly.size(); ++k) {
          mesh.indices.push_back(ci);
          mesh.indices.push_back(vertexOut(poly[k]));
          mesh.indices.push_back(vertexOut(poly[(k + 1) % poly.size()]));
        }
      }
    }
  }
  const std::vector<int32_t> partOf = partsOf(A, faces, out.parts);
  for (int32_t v : source) out.vertexPart.push_back(uint32_t(partOf[size_t(v)]));
  mergeFaces(A, faces, partOf, spacing, out);
  return out;
}

}  // namespace fgsg::rt::synthesis::continuous
