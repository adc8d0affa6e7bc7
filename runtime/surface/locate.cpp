#include "runtime/surface/locate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace fgsg::rt::surface {

namespace {

// Faces per leaf: few enough that a leaf costs about as much as descending further.
constexpr int kLeafFaces = 4;

double boxDistanceSquared(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  const Vec3 d = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
  return d.squaredNorm();
}

}  // namespace

// Ericson, Real-Time Collision Detection, 5.1.5: find the Voronoi region of p (a corner,
// an edge or the inside) and project onto it.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                            Vec3& bary) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) {
    bary = Vec3(1, 0, 0);
    return a;
  }
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) {
    bary = Vec3(0, 1, 0);
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    bary = Vec3(1 - v, v, 0);
    return a + v * ab;
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) {
    bary = Vec3(0, 0, 1);
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    bary = Vec3(1 - w, 0, w);
    return a + w * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    bary = Vec3(0, 1 - w, w);
    return b + w * (c - b);
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  bary = Vec3(1 - v - w, v, w);
  return a + v * ab + w * ac;
}

SurfaceLocator::SurfaceLocator(const SurfaceMesh& mesh) : mesh_(mesh) {
  const int nf = int(mesh.faces.size());
  order_.resize(nf);
  std::iota(order_.begin(), order_.end(), 0);
  std::vector<Vec3> centroids(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& t = mesh.faces[f];
    centroids[f] = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3;
  }
  nodes_.reserve(nf > 0 ? 2 * (nf / kLeafFaces + 1) : 0);
  if (nf > 0) build(0, nf, centroids);
}

// Splits at the median centroid along the widest axis of the centroids' box: balanced
// trees whatever the triangle sizes.
int SurfaceLocator::build(int first, int count, std::vector<Vec3>& centroids) {
  const int index = int(nodes_.size());
  nodes_.emplace_back();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  Vec3 clo = lo, chi = hi;
  for (int i = first; i < first + count; ++i) {
    const auto& t = mesh_.faces[order_[i]];
    for (int v : t) {
      lo = lo.cwiseMin(mesh_.vertices[v]);
      hi = hi.cwiseMax(mesh_.vertices[v]);
    }
    clo = clo.cwiseMin(centroids[order_[i]]);
    chi = chi.cwiseMax(centroids[order_[i]]);
  }
  nodes_[index].lo = lo;
  nodes_[index].hi = hi;
  if (count <= kLeafFaces) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count,
                   [&](int f, int g) { return centroids[f][axis] < centroids[g][axis]; });
  build(first, half, centroids);
  const int right = build(first + half, count - half, centroids);
  nodes_[index].right = right;
  return index;
}

// A point as far from the surface as `p` in the same direction, but near enough that
// squared distances stay finite: beyond ~1e154 they overflow to infinity and every box
// would look as far as the best face. Seen from 1e12 surface sizes away the answer is the
// same point (the surface's extreme point in that direction) up to rounding.
Vec3 SurfaceLocator::withinRange(const Vec3& p) const {
  const Vec3 centre = (nodes_[0].lo + nodes_[0].hi) / 2;
  const double size = std::max((nodes_[0].hi - nodes_[0].lo).norm(), 1e-300);
  const double reach = 1e12 * size;
  // Infinite coordinates are taken as the largest finite ones: a direction remains.
  const double big = std::numeric_limits<double>::max();
  const Vec3 q = p.cwiseMax(-big).cwiseMin(big);
  const Vec3 d = q - centre;
  const double scale = d.cwiseAbs().maxCoeff();  // |d| without overflowing
  if (!std::isfinite(scale) || scale * std::sqrt(3.0) <= reach) return q;
  const Vec3 unit = (d / scale).normalized();
  return centre + reach * unit;
}

SurfacePoint SurfaceLocator::closestPoint(const Vec3& pIn, double* distance) const {
  SurfacePoint best;
  double bestSq = std::numeric_limits<double>::infinity();
  if (nodes_.empty() || pIn.hasNaN()) {
    if (distance) *distance = pIn.hasNaN() ? std::numeric_limits<double>::quiet_NaN() : bestSq;
    return best;
  }
  const Vec3 p = withinRange(pIn);
  // Depth first, nearer child first, pruning boxes farther than the best so far.
  std::vector<std::pair<double, int>> stack = {
      {boxDistanceSquared(p, nodes_[0].lo, nodes_[0].hi), 0}};
  while (!stack.empty()) {
    const auto [boxSq, index] = stack.back();
    stack.pop_back();
    if (best.valid() && boxSq >= bestSq) continue;
    const Node& node = nodes_[index];
    if (node.right < 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const int f = order_[i];
        const auto& t = mesh_.faces[f];
        Vec3 bary;
        const Vec3 q = closestPointOnTriangle(p, mesh_.vertices[t[0]], mesh_.vertices[t[1]],
                                              mesh_.vertices[t[2]], bary);
        const double sq = (q - p).squaredNorm();
        if (sq < bestSq || !best.valid()) {
          bestSq = sq;
          best.face = f;
          best.bary = bary;
        }
      }
      continue;
    }
    const int left = index + 1, right = node.right;
    const double dl = boxDistanceSquared(p, nodes_[left].lo, nodes_[left].hi);
    const double dr = boxDistanceSquared(p, nodes_[right].lo, nodes_[right].hi);
    // Pushed last, popped first: the nearer child.
    if (dl < dr) {
      stack.push_back({dr, right});
      stack.push_back({dl, left});
    } else {
      stack.push_back({dl, left});
      stack.push_back({dr, right});
    }
  }
  if (distance) *distance = p == pIn ? std::sqrt(bestSq) : (best.position(mesh_) - pIn).norm();
  return best;
}

SurfacePoint closestPoint(const SurfaceMesh& mesh, const Vec3& p) {
  return SurfaceLocator(mesh).closestPoint(p);
}

SurfacePoint atVertex(const SurfaceMesh& mesh, int v) {
  SurfacePoint s;
  if (v < 0 || size_t(v) >= mesh.vertexFace.size() || mesh.vertexFace[v] < 0) return s;
  s.face = mesh.vertexFace[v];
  s.bary = Vec3::Zero();
  s.bary[mesh.cornerOf(s.face, v)] = 1;
  return s;
}

SurfacePoint atEdge(const SurfaceMesh& mesh, int face, int k, double t) {
  SurfacePoint s;
  s.face = face;
  s.bary = Vec3::Zero();
  s.bary[k] = 1 - t;
  s.bary[(k + 1) % 3] = t;
  return s;
}

}  // namespace fgsg::rt::surface
