#include "runtime/synthesis/continuous/boundary_surface.h"

#include <algorithm>
#include <cmath>

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
  auto vertexOut = [&](int32_t v) -> uint32_t {
    if (meshIndex[size_t(v)] < 0) {
      const DVec3 p = A.position(size_t(v));
      meshIndex[size_t(v)] = int32_t(mesh.vertexCount());
      for (double c : p) mesh.positions.push_back(float(c * spacing));
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
        for (size_t k = 0; k < poly.size(); ++k) {
          mesh.indices.push_back(ci);
          mesh.indices.push_back(vertexOut(poly[k]));
          mesh.indices.push_back(vertexOut(poly[(k + 1) % poly.size()]));
        }
      }
    }
  }
  return out;
}

}  // namespace fgsg::rt::synthesis::continuous
