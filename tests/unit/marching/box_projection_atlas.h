// A crude but valid atlas for any triangle mesh, for tests and the benchmark until
// atlas::buildAtlas lands: faces grouped by the axis (+-x, +-y, +-z) their normal leans
// to most, grown edge by edge into charts whose projections onto that axis's plane do
// not overlap, and shelf-packed with a gutter. Distorted (a projection) and made of many
// small charts meeting at many corners: a hard case for marching, which is the point.
#pragma once

#include "runtime/atlas/atlas.h"
#include "runtime/surface/surface_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <unordered_map>
#include <vector>

namespace fgsg::rt::marching::testing {

namespace box_projection {

// Image axes (u, v) for each projection axis, u x v the axis, so that a face leaning to
// the axis keeps its counter-clockwise order.
inline const std::array<std::array<Vec3, 2>, 6> kPlanes = {{
    {Vec3::UnitY(), Vec3::UnitZ()},   // +x
    {Vec3::UnitZ(), Vec3::UnitY()},   // -x
    {Vec3::UnitZ(), Vec3::UnitX()},   // +y
    {Vec3::UnitX(), Vec3::UnitZ()},   // -y
    {Vec3::UnitX(), Vec3::UnitY()},   // +z
    {Vec3::UnitY(), Vec3::UnitX()},   // -z
}};

using Triangle = std::array<atlas::Vec2, 3>;

// Whether two triangles' interiors overlap (separating axes: the six edge normals;
// touching along an edge or at a corner is not overlapping).
inline bool overlap(const Triangle& a, const Triangle& b, double eps) {
  for (const Triangle* t : {&a, &b})
    for (int k = 0; k < 3; ++k) {
      const atlas::Vec2 e = (*t)[(k + 1) % 3] - (*t)[k];
      const atlas::Vec2 n(-e.y(), e.x());
      double loA = INFINITY, hiA = -INFINITY, loB = INFINITY, hiB = -INFINITY;
      for (int i = 0; i < 3; ++i) {
        loA = std::min(loA, n.dot(a[i])), hiA = std::max(hiA, n.dot(a[i]));
        loB = std::min(loB, n.dot(b[i])), hiB = std::max(hiB, n.dot(b[i]));
      }
      const double slack = eps * n.norm();
      if (hiA <= loB + slack || hiB <= loA + slack) return false;  // separated
    }
  return true;
}

// Shelf packing of w x h rectangles (texels, gutters included) into a side x side
// square: their lower-left corners, or false when they do not fit.
inline bool shelfPack(const std::vector<atlas::Vec2>& sizes, const std::vector<int>& order, double side,
                      std::vector<atlas::Vec2>& at) {
  at.assign(sizes.size(), atlas::Vec2::Zero());
  double x = 0, y = 0, shelf = 0;
  for (int i : order) {
    if (x + sizes[i].x() > side) x = 0, y += shelf, shelf = 0;
    if (sizes[i].x() > side || y + sizes[i].y() > side) return false;
    at[i] = atlas::Vec2(x, y);
    x += sizes[i].x();
    shelf = std::max(shelf, sizes[i].y());
  }
  return true;
}

}  // namespace box_projection

inline atlas::Atlas boxProjectionAtlas(const surface::SurfaceMesh& mesh, int resolution = 1024,
                                       double gutterTexels = 2) {
  using namespace box_projection;
  const int nf = int(mesh.faceCount());
  std::vector<int> axis(nf);
  std::vector<Triangle> projected(nf);
  for (int f = 0; f < nf; ++f) {
    const Vec3& n = mesh.faceNormals[f];
    int best = 0;
    for (int a = 1; a < 6; ++a)
      if (n[a / 2] * (a % 2 ? -1 : 1) > n[best / 2] * (best % 2 ? -1 : 1)) best = a;
    axis[f] = best;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.vertices[mesh.faces[f][k]];
      projected[f][k] = atlas::Vec2(p.dot(kPlanes[best][0]), p.dot(kPlanes[best][1]));
    }
  }
  // Charts grown face by face over shared edges; a face whose projection would overlap
  // the chart's is left for a later chart. A grid of cells finds the faces near one.
  const double cell = 2 * mesh.meanEdgeLength, eps = 1e-9 * mesh.meanEdgeLength;
  std::vector<int> chartOf(nf, -1);
  std::unordered_map<int64_t, std::vector<int>> grid;
  auto cellsOf = [&](const Triangle& t, auto&& visit) {
    const atlas::Vec2 lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]) / cell, hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]) / cell;
    for (int64_t y = int64_t(std::floor(lo.y())); y <= int64_t(std::floor(hi.y())); ++y)
      for (int64_t x = int64_t(std::floor(lo.x())); x <= int64_t(std::floor(hi.x())); ++x)
        visit((y << 32) ^ (x & 0xffffffff));
  };
  int charts = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (chartOf[seed] >= 0) continue;
    const int chart = charts++;
    grid.clear();
    std::deque<int> queue{seed};
    chartOf[seed] = chart;
    cellsOf(projected[seed], [&](int64_t c) { grid[c].push_back(seed); });
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k) {
        const int g = mesh.neighbours[f][k];
        if (g < 0 || chartOf[g] >= 0 || axis[g] != axis[f]) continue;
        bool clash = false;
        cellsOf(projected[g], [&](int64_t c) {
          const auto it = grid.find(c);
          if (it == grid.end() || clash) return;
          for (int h : it->second)
            if (overlap(projected[g], projected[h], eps)) {
              clash = true;
              break;
            }
        });
        if (clash) continue;
        chartOf[g] = chart;
        cellsOf(projected[g], [&](int64_t c) { grid[c].push_back(g); });
        queue.push_back(g);
      }
    }
  }
  // Packing: the largest scale (texels per unit) at which every chart's box, with its
  // gutter on each side, fits on shelves.
  std::vector<atlas::Vec2> low(charts, atlas::Vec2::Constant(INFINITY)), high(charts, atlas::Vec2::Constant(-INFINITY));
  for (int f = 0; f < nf; ++f)
    for (const auto& p : projected[f]) {
      low[chartOf[f]] = low[chartOf[f]].cwiseMin(p);
      high[chartOf[f]] = high[chartOf[f]].cwiseMax(p);
    }
  std::vector<int> order(charts);
  for (int c = 0; c < charts; ++c) order[c] = c;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return high[a].y() - low[a].y() != high[b].y() - low[b].y() ? high[a].y() - low[a].y() > high[b].y() - low[b].y()
                                                                : a < b;
  });
  std::vector<atlas::Vec2> sizes(charts), at;
  auto fits = [&](double scale) {
    for (int c = 0; c < charts; ++c) sizes[c] = (high[c] - low[c]) * scale + atlas::Vec2::Constant(2 * gutterTexels + 1);
    return shelfPack(sizes, order, resolution, at);
  };
  double lo = 0, hi = resolution / mesh.meanEdgeLength;
  for (int k = 0; k < 50; ++k) (fits(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
  fits(lo);
  atlas::Atlas out;
  out.chartCount = charts;
  out.resolution = resolution;
  out.faceChart = chartOf;
  out.cornerUV.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const int c = chartOf[f];
    for (int k = 0; k < 3; ++k)
      out.cornerUV[f][k] =
          (at[c] + atlas::Vec2::Constant(gutterTexels + 0.5) + (projected[f][k] - low[c]) * lo) / resolution;
  }
  return out;
}

}  // namespace fgsg::rt::marching::testing
