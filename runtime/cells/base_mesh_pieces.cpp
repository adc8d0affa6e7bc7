// A labelled base mesh from separately written pieces (base_mesh_pieces.h).
#include "runtime/cells/base_mesh_pieces.h"

#include "runtime/surface/load_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace fgsg::rt::cells {
namespace {

std::string at(const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x(), p.y(), p.z());
  return text;
}

// Points in a uniform grid of cubes, found by the cubes a box overlaps.
class PointGrid {
 public:
  explicit PointGrid(double cell) : cell_(cell) {}
  std::array<int64_t, 3> key(const Vec3& p) const {
    return {int64_t(std::floor(p.x() / cell_)), int64_t(std::floor(p.y() / cell_)), int64_t(std::floor(p.z() / cell_))};
  }
  void add(const Vec3& p, int id) { cells_[key(p)].push_back(id); }
  template <class F>
  void near(const Vec3& lo, const Vec3& hi, F&& visit) const {
    const auto a = key(lo), b = key(hi);
    for (int64_t x = a[0]; x <= b[0]; ++x)
      for (int64_t y = a[1]; y <= b[1]; ++y)
        for (int64_t z = a[2]; z <= b[2]; ++z) {
          auto it = cells_.find({x, y, z});
          if (it != cells_.end())
            for (int id : it->second) visit(id);
        }
  }

 private:
  struct Hash {
    size_t operator()(const std::array<int64_t, 3>& k) const {
      return size_t(k[0] * 73856093) ^ size_t(k[1] * 19349663) ^ size_t(k[2] * 83492791);
    }
  };
  double cell_;
  std::unordered_map<std::array<int64_t, 3>, std::vector<int>, Hash> cells_;
};

Vec3 newell(const std::vector<Vec3>& v, const std::vector<int>& loop) {
  Vec3 n = Vec3::Zero();
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3& a = v[loop[i]];
    const Vec3& b = v[loop[(i + 1) % loop.size()]];
    n += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()), (a.x() - b.x()) * (a.y() + b.y()));
  }
  return n;
}

// Ear clipping in the plane of the (oriented) loop; only ears with area, so corners in a
// row on a side stay in the mesh (they are where a neighbouring piece's corner joins).
bool earClip(const std::vector<Vec3>& v, std::vector<int> loop, std::vector<std::array<int, 3>>& out) {
  const Vec3 n = newell(v, loop).normalized();
  const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
  auto p2 = [&](int i) { return Eigen::Vector2d(v[i].dot(u), v[i].dot(w)); };
  auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  };
  // Relative to the ear's size, as surface validation judges degenerate triangles.
  auto flat = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return 1e-9 * std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  };
  while (loop.size() > 3) {
    bool clipped = false;
    for (size_t i = 0; i < loop.size() && !clipped; ++i) {
      const size_t ip = (i + loop.size() - 1) % loop.size(), in = (i + 1) % loop.size();
      const Eigen::Vector2d a = p2(loop[ip]), b = p2(loop[i]), c = p2(loop[in]);
      const double minArea = flat(a, b, c);
      if (!(cross(a, b, c) > minArea)) continue;  // reflex or flat: not an ear
      bool empty = true;
      for (size_t k = 0; k < loop.size() && empty; ++k) {
        if (k == ip || k == i || k == in) continue;
        const Eigen::Vector2d q = p2(loop[k]);
        if (cross(a, b, q) >= -minArea && cross(b, c, q) >= -minArea && cross(c, a, q) >= -minArea) empty = false;
      }
      if (!empty) continue;
      out.push_back({loop[ip], loop[i], loop[in]});
      loop.erase(loop.begin() + long(i));
      clipped = true;
    }
    if (!clipped) return false;
  }
  const Eigen::Vector2d a = p2(loop[0]), b = p2(loop[1]), c = p2(loop[2]);
  if (!(cross(a, b, c) > flat(a, b, c))) return false;
  out.push_back({loop[0], loop[1], loop[2]});
  return true;
}

}  // namespace

LabelledMesh labelledMeshFromPolygons(const std::vector<LabelledPolygon>& pieces) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const auto& piece : pieces)
    for (const Vec3& p : piece.points) {
      if (!p.allFinite()) throw std::runtime_error("a base piece has a corner that is not finite");
      lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    }
  const double extent = (hi - lo).norm();
  if (!(extent > 0)) throw std::runtime_error("the base part left no pieces with an area");
  const double tol = 1e-9 * extent;

  // Welding.
  std::vector<Vec3> verts;
  PointGrid weldGrid(4 * tol);
  auto weld = [&](const Vec3& p) {
    int found = -1;
    weldGrid.near(p - Vec3::Constant(tol), p + Vec3::Constant(tol), [&](int id) {
      if (found < 0 && (verts[id] - p).norm() <= tol) found = id;
    });
    if (found >= 0) return found;
    verts.push_back(p);
    weldGrid.add(p, int(verts.size() - 1));
    return int(verts.size() - 1);
  };
  std::vector<std::vector<int>> loops;
  std::vector<int> loopLabel;
  std::vector<std::string> labels;
  std::map<std::string, int> labelIndex;
  for (const auto& piece : pieces) {
    std::vector<int> loop;
    for (const Vec3& p : piece.points) {
      const int id = weld(p);
      if (loop.empty() || loop.back() != id) loop.push_back(id);
    }
    while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
    if (loop.size() < 3 || !(newell(verts, loop).norm() > tol * tol)) continue;  // no area: nothing to cover
    auto [it, fresh] = labelIndex.emplace(piece.label, int(labels.size()));
    if (fresh) labels.push_back(piece.label);
    loops.push_back(std::move(loop));
    loopLabel.push_back(it->second);
  }
  if (loops.empty()) throw std::runtime_error("the base part left no pieces with an area");

  // T-junctions: corners of other pieces lying on a side are inserted into it.
  const double cell = std::max(extent / std::max(1.0, std::cbrt(double(verts.size()))), 4 * tol);
  PointGrid grid(cell);
  for (size_t i = 0; i < verts.size(); ++i) grid.add(verts[i], int(i));
  for (auto& loop : loops) {
    std::vector<int> out;
    for (size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      const Vec3 pa = verts[a], d = verts[b] - pa;
      const double len2 = d.squaredNorm();
      std::vector<std::pair<double, int>> on;
      grid.near(pa.cwiseMin(verts[b]) - Vec3::Constant(tol), pa.cwiseMax(verts[b]) + Vec3::Constant(tol), [&](int id) {
        if (id == a || id == b) return;
        const double t = (verts[id] - pa).dot(d) / len2;
        if (t > 0 && t < 1 && (pa + t * d - verts[id]).norm() <= tol) on.emplace_back(t, id);
      });
      std::sort(on.begin(), on.end());
      out.push_back(a);
      for (const auto& [t, id] : on) out.push_back(id);
    }
    loop = std::move(out);
  }

  // Sides shared by two pieces; more is not a surface.
  std::map<std::pair<int, int>, std::vector<std::pair<int, bool>>> sides;  // -> (piece, walked low to high)
  for (size_t k = 0; k < loops.size(); ++k)
    for (size_t i = 0; i < loops[k].size(); ++i) {
      const int a = loops[k][i], b = loops[k][(i + 1) % loops[k].size()];
      auto& users = sides[{std::min(a, b), std::max(a, b)}];
      users.emplace_back(int(k), a < b);
      if (users.size() > 2)
        throw std::runtime_error("three or more base pieces meet at the edge from " + at(verts[std::min(a, b)]) +
                                 " to " + at(verts[std::max(a, b)]) +
                                 ": pieces may only meet two at an edge (is a piece written twice?)");
    }

  // Orientation: each connected part agrees with its largest piece.
  std::vector<double> area(loops.size());
  for (size_t k = 0; k < loops.size(); ++k) area[k] = newell(verts, loops[k]).norm();
  std::vector<int> order(loops.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return area[x] > area[y]; });
  std::vector<int> flip(loops.size(), -1);  // -1 unvisited, 0 kept, 1 reversed
  std::vector<std::vector<std::pair<int, bool>>> touching(loops.size());  // (other piece, same direction)
  for (const auto& [edge, users] : sides)
    if (users.size() == 2) {
      const bool same = users[0].second == users[1].second;
      touching[users[0].first].emplace_back(users[1].first, same);
      touching[users[1].first].emplace_back(users[0].first, same);
    }
  for (int seed : order) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    std::vector<int> todo{seed};
    while (!todo.empty()) {
      const int k = todo.back();
      todo.pop_back();
      for (const auto& [other, same] : touching[k]) {
        const int want = flip[k] ^ int(same);  // walking a shared side the same way: one of them turns
        if (flip[other] < 0) flip[other] = want, todo.push_back(other);
        else if (flip[other] != want)
          throw std::runtime_error("the base pieces around " + at(verts[loops[other][0]]) +
                                   " cannot be given one outside (a one-sided surface, like a Moebius strip)");
      }
    }
  }

  LabelledMesh result;
  result.groups = labels;
  auto& mesh = result.mesh;
  std::vector<int> remap(verts.size(), -1);
  for (size_t k = 0; k < loops.size(); ++k) {
    if (flip[k]) std::reverse(loops[k].begin(), loops[k].end());
    std::vector<std::array<int, 3>> tris;
    if (!earClip(verts, loops[k], tris))
      throw std::runtime_error("the base piece at " + at(verts[loops[k][0]]) +
                               " is not a simple flat polygon (it crosses itself or folds)");
    for (auto& t : tris) {
      for (int& id : t) {
        if (remap[id] < 0) remap[id] = int(mesh.vertices.size()), mesh.vertices.push_back(verts[id]);
        id = remap[id];
      }
      mesh.faces.push_back(t);
      result.triangleGroup.push_back(loopLabel[k]);
    }
  }
  std::vector<std::string> problems;
  if (!surface::validateSurface(mesh, problems)) {
    std::string msg = "the base pieces do not make a valid surface: ";
    for (size_t i = 0; i < problems.size(); ++i) msg += (i ? "; " : "") + problems[i];
    throw std::runtime_error(msg);
  }
  mesh.buildTopology();
  return result;
}

}  // namespace fgsg::rt::cells
