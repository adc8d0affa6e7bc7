#include "runtime/synthesis/continuous/inside_test.h"

#include <Eigen/Geometry>
#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>

namespace fgsg::rt::synthesis::continuous {

namespace {

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

V3 at(const ExampleSolid& s, int v) {
  const DVec3& p = s.vertices[size_t(v)];
  return {p[0], p[1], p[2]};
}

double cross2(const V2& a, const V2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Relative sizes (of the example's extent) below which a point counts as on an edge's
// projection or on a face: far below the step labels take off the surface (at least
// about 1e-6 of it), far above rounding.
constexpr double kOnEdge = 1e-10;
constexpr double kOnFace = 1e-10;
// Grid entries (triangle x cell) past which the grid is not built (every point then
// falls back): only a solid of huge, thin fan triangles comes near.
constexpr size_t kMaxEntries = size_t(1) << 26;

}  // namespace

InsideTest::InsideTest(const ExampleSolid& solid) : solid_(solid) {
  // Parallel to no face: face directions are small integer vectors, and no integer
  // combination of these irrational components is zero.
  ray_ = V3(1.0 / std::sqrt(3.0), 1.0 / 3.14159265358979323846, std::sqrt(2.0) / 2.7182818284590452).normalized();
  u_ = ray_.cross(V3::UnitX()).normalized();
  v_ = ray_.cross(u_);
  const double extent = std::max(solid.diagonal, 1e-300);
  onFace_ = kOnFace * extent;
  V2 lo = V2::Constant(INFINITY), hi = -lo;
  for (const auto& poly : solid.polygons)
    for (size_t i = 1; i + 1 < poly.size(); ++i) {
      Triangle t;
      const V3 a = at(solid, poly[0]), b = at(solid, poly[i]), c = at(solid, poly[i + 1]);
      t.a = a;
      t.n = (b - a).cross(c - a);
      if (std::abs(t.n.dot(ray_)) <= 1e-12 * t.n.norm()) continue;  // edge-on: crossed by no ray (its neighbours are)
      const V3 corners[3] = {a, b, c};
      for (int k = 0; k < 3; ++k) {
        t.p[k] = V2(u_.dot(corners[k]), v_.dot(corners[k]));
        lo = lo.cwiseMin(t.p[k]);
        hi = hi.cwiseMax(t.p[k]);
      }
      for (int k = 0; k < 3; ++k) t.tol[k] = kOnEdge * extent * (t.p[(k + 1) % 3] - t.p[k]).norm();
      triangles_.push_back(t);
    }
  if (triangles_.empty()) return;
  // About one triangle per cell.
  const int side = std::clamp(int(std::sqrt(double(triangles_.size()))), 1, 1024);
  nx_ = ny_ = side;
  // A margin, so that a point on the outline of the projections (its ray grazes the
  // solid) finds the triangles there and falls back, rounding either way.
  const V2 margin = V2::Constant(1e-6 * (hi - lo).maxCoeff() + 1e-300);
  lo -= margin;
  hi += margin;
  lo_ = lo;
  cell_ = ((hi - lo) / double(side)).cwiseMax(V2::Constant(1e-300));
  auto cellRange = [&](const Triangle& t, int& x0, int& x1, int& y0, int& y1) {
    V2 tlo = t.p[0].cwiseMin(t.p[1]).cwiseMin(t.p[2]), thi = t.p[0].cwiseMax(t.p[1]).cwiseMax(t.p[2]);
    x0 = std::clamp(int((tlo.x() - lo_.x()) / cell_.x()) - 1, 0, nx_ - 1);
    x1 = std::clamp(int((thi.x() - lo_.x()) / cell_.x()) + 1, 0, nx_ - 1);
    y0 = std::clamp(int((tlo.y() - lo_.y()) / cell_.y()) - 1, 0, ny_ - 1);
    y1 = std::clamp(int((thi.y() - lo_.y()) / cell_.y()) + 1, 0, ny_ - 1);
  };
  std::vector<uint32_t> count(size_t(nx_) * size_t(ny_) + 1, 0);
  size_t total = 0;
  for (const Triangle& t : triangles_) {
    int x0, x1, y0, y1;
    cellRange(t, x0, x1, y0, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) ++count[size_t(y) * size_t(nx_) + size_t(x)];
    total += size_t(x1 - x0 + 1) * size_t(y1 - y0 + 1);
    if (total > kMaxEntries) {
      nx_ = ny_ = 0;  // no grid: windingNumber() for every point
      return;
    }
  }
  start_.assign(count.size(), 0);
  for (size_t c = 1; c < count.size(); ++c) start_[c] = start_[c - 1] + count[c - 1];
  entries_.resize(total);
  std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
  for (uint32_t i = 0; i < triangles_.size(); ++i) {
    int x0, x1, y0, y1;
    cellRange(triangles_[i], x0, x1, y0, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) entries_[fill[size_t(y) * size_t(nx_) + size_t(x)]++] = i;
  }
}

bool InsideTest::inside(const DVec3& point) const {
  const V3 p(point[0], point[1], point[2]);
  if (nx_ == 0) {
    if (!triangles_.empty()) ++fallbacks_;
    return windingNumber(solid_, point) > 0.5;
  }
  const V2 q(u_.dot(p), v_.dot(p));
  const V2 g = (q - lo_).cwiseQuotient(cell_);
  // The grid covers every projection (with a cell to spare): a ray outside it meets nothing.
  if (!(g.x() >= 0 && g.y() >= 0 && g.x() < nx_ && g.y() < ny_)) return false;
  const size_t c = size_t(int(g.y())) * size_t(nx_) + size_t(int(g.x()));
  int crossings = 0;
  for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
    const Triangle& t = triangles_[entries_[k]];
    double e[3];
    bool pos = false, neg = false, on = false;
    for (int j = 0; j < 3; ++j) {
      e[j] = cross2(t.p[(j + 1) % 3] - t.p[j], q - t.p[j]);
      if (std::abs(e[j]) <= t.tol[j]) on = true;
      else (e[j] > 0 ? pos : neg) = true;
    }
    if (pos && neg) continue;  // clearly beside it
    const double along = t.n.dot(ray_);
    const double s = t.n.dot(t.a - p) / along;  // where the ray meets its plane
    if (on || std::abs(s) * t.n.norm() <= onFace_ * std::abs(along)) {
      ++fallbacks_;  // on an edge of the projection, or on the face: the exact sum
      return windingNumber(solid_, point) > 0.5;
    }
    if (s > 0) crossings += along > 0 ? 1 : -1;
  }
  return crossings > 0;
}

struct NearestVertex::Tree {
  struct Cloud {
    const ExampleSolid& s;
    size_t kdtree_get_point_count() const { return s.vertices.size(); }
    double kdtree_get_pt(size_t i, size_t d) const { return s.vertices[i][d]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
  };
  using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3, uint32_t>;
  Cloud cloud;
  Index index;
  explicit Tree(const ExampleSolid& s) : cloud{s}, index(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
};

NearestVertex::NearestVertex(const ExampleSolid& solid) : tree_(std::make_unique<Tree>(solid)) {}
NearestVertex::~NearestVertex() = default;

double NearestVertex::distance(const DVec3& p, int skip) const {
  uint32_t found[2];
  double squared[2];
  const size_t n = tree_->index.knnSearch(p.data(), 2, found, squared);
  for (size_t k = 0; k < n; ++k)
    if (int(found[k]) != skip) return std::sqrt(squared[k]);
  return INFINITY;
}

}  // namespace fgsg::rt::synthesis::continuous
