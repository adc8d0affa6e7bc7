// Meshes with hand-laid atlases for the marching tests and benchmark, built before
// atlas::buildAtlas exists: each chart is an exact isometry of its faces (scaled), so a
// straight line in a chart's image is a straight line on the surface.
#pragma once

#include "runtime/atlas/atlas.h"
#include "runtime/surface/surface_mesh.h"

#include <array>
#include <cmath>
#include <map>

namespace fgsg::rt::marching::testing {

using atlas::Vec2;

struct ChartedMesh {
  surface::SurfaceMesh mesh;
  atlas::Atlas atlas;
};

constexpr double kPi = 3.14159265358979323846;

// A flat side x side square in the XY plane centred at the origin, normal +Z: an
// n x n vertex grid, one chart, u = x and v = y scaled into the unit square with
// `marginTexels` empty texels around.
inline ChartedMesh flatSquare(int n = 20, double side = 2.0, int resolution = 1024, double marginTexels = 4) {
  ChartedMesh c;
  auto& m = c.mesh;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.vertices.push_back(Vec3(side * (double(i) / (n - 1) - 0.5), side * (double(j) / (n - 1) - 0.5), 0));
  const double margin = marginTexels / resolution;
  auto uv = [&](int v) {
    const Vec3& p = m.vertices[v];
    return Vec2(margin + (1 - 2 * margin) * (p.x() / side + 0.5), margin + (1 - 2 * margin) * (p.y() / side + 0.5));
  };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, d = a + n, e = d + 1;
      for (const std::array<int, 3>& f : {std::array<int, 3>{a, b, e}, std::array<int, 3>{a, e, d}}) {
        m.faces.push_back(f);
        c.atlas.cornerUV.push_back({uv(f[0]), uv(f[1]), uv(f[2])});
        c.atlas.faceChart.push_back(0);
      }
    }
  c.atlas.chartCount = 1;
  c.atlas.resolution = resolution;
  m.buildTopology();
  return c;
}

// flatSquare(21, 2.0, resolution, 8) cut down x = 0 (a column of vertices) into two
// charts, the right one's image moved `gapTexels` right, then both squeezed to 0.9 of
// their width about the image's middle (an affine map, not a conformal one).
inline ChartedMesh splitSquare(double gapTexels, int resolution = 512) {
  ChartedMesh c = flatSquare(21, 2.0, resolution, 8);
  for (size_t f = 0; f < c.mesh.faces.size(); ++f) {
    const auto& v = c.mesh.faces[f];
    const double cx = (c.mesh.vertices[v[0]].x() + c.mesh.vertices[v[1]].x() + c.mesh.vertices[v[2]].x()) / 3;
    c.atlas.faceChart[f] = cx < 0 ? 0 : 1;
    for (auto& uv : c.atlas.cornerUV[f]) {
      if (cx >= 0) uv.x() += gapTexels / resolution;
      uv.x() = 0.5 + (uv.x() - 0.5) * 0.9;
    }
  }
  c.atlas.chartCount = 2;
  return c;
}

// The cube [-0.5, 0.5]^3, `quads` x `quads` squares per side (two triangles each). Each
// side is a chart; the six lie in a 3 x 2 grid of the unit square, `gutterTexels` from
// their cell's sides, turned by 0, 1, 2 or 3 quarter turns (side k by k % 4) so that
// jumps between them must turn the marching direction.
inline ChartedMesh chartedCube(int quads = 8, int resolution = 1024, double gutterTexels = 4) {
  struct Side {
    std::array<int, 3> origin, u, v;  // on the integer lattice of the corners, u x v outwards
  };
  const std::array<Side, 6> sides = {{
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},    // +Z
      {{0, 1, 0}, {1, 0, 0}, {0, -1, 0}},   // -Z
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},    // +X
      {{0, 1, 0}, {0, -1, 0}, {0, 0, 1}},   // -X
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},    // +Y
      {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},    // -Y
  }};
  ChartedMesh c;
  auto& m = c.mesh;
  std::map<std::array<int, 3>, int> index;
  auto vertex = [&](const std::array<int, 3>& lattice) {
    const auto [it, added] = index.emplace(lattice, int(m.vertices.size()));
    if (added)
      m.vertices.push_back(Vec3(double(lattice[0]) / quads - 0.5, double(lattice[1]) / quads - 0.5,
                                double(lattice[2]) / quads - 0.5));
    return it->second;
  };
  const double gutter = gutterTexels / resolution;
  const double chartSide = 1.0 / 3 - 2 * gutter;
  for (int k = 0; k < 6; ++k) {
    const Side& s = sides[k];
    const Vec2 cell(double(k % 3) / 3 + gutter, double(k / 3) / 2 + gutter);
    auto uv = [&](int i, int j) {
      const double a = double(i) / quads, b = double(j) / quads;
      Vec2 turned;
      switch (k % 4) {
        case 0: turned = Vec2(a, b); break;
        case 1: turned = Vec2(1 - b, a); break;
        case 2: turned = Vec2(1 - a, 1 - b); break;
        default: turned = Vec2(b, 1 - a); break;
      }
      return Vec2(cell + chartSide * turned);
    };
    auto corner = [&](int i, int j) {
      std::array<int, 3> p;
      for (int d = 0; d < 3; ++d) p[d] = s.origin[d] * quads + i * s.u[d] + j * s.v[d];
      return vertex(p);
    };
    for (int j = 0; j < quads; ++j)
      for (int i = 0; i < quads; ++i) {
        const std::array<std::array<int, 2>, 3> t1 = {{{i, j}, {i + 1, j}, {i + 1, j + 1}}};
        const std::array<std::array<int, 2>, 3> t2 = {{{i, j}, {i + 1, j + 1}, {i, j + 1}}};
        for (const auto& t : {t1, t2}) {
          m.faces.push_back({corner(t[0][0], t[0][1]), corner(t[1][0], t[1][1]), corner(t[2][0], t[2][1])});
          c.atlas.cornerUV.push_back({uv(t[0][0], t[0][1]), uv(t[1][0], t[1][1]), uv(t[2][0], t[2][1])});
          c.atlas.faceChart.push_back(k);
        }
      }
  }
  c.atlas.chartCount = 6;
  c.atlas.resolution = resolution;
  m.buildTopology();
  return c;
}

// An open cylinder (no caps) of radius r around the Z axis from z = -h/2 to h/2:
// `segments` around, `rows` along. `charts` charts of segments / charts columns each,
// unrolled (u along the chords, v = z), in a 2 x 2 grid (charts <= 4) with
// `gutterTexels` around each.
inline ChartedMesh chartedCylinder(double r = 1, double h = 2, int segments = 48, int rows = 24, int charts = 4,
                                   int resolution = 1024, double gutterTexels = 4) {
  ChartedMesh c;
  auto& m = c.mesh;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * kPi * i / segments;
      m.vertices.push_back(Vec3(r * std::cos(a), r * std::sin(a), h * (double(j) / rows - 0.5)));
    }
  const int columns = segments / charts;
  const double chord = 2 * r * std::sin(kPi / segments);
  const double gutter = gutterTexels / resolution;
  const double scale = (0.5 - 2 * gutter) / std::max(columns * chord, h);
  auto id = [&](int i, int j) { return j * segments + i % segments; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < segments; ++i) {
      const int chart = i / columns, first = chart * columns;
      const Vec2 cell(double(chart % 2) / 2 + gutter, double(chart / 2) / 2 + gutter);
      auto uv = [&](int ci, int cj) { return Vec2(cell + scale * Vec2((ci - first) * chord, h * cj / rows)); };
      const std::array<std::array<int, 2>, 3> t1 = {{{i, j}, {i + 1, j}, {i + 1, j + 1}}};
      const std::array<std::array<int, 2>, 3> t2 = {{{i, j}, {i + 1, j + 1}, {i, j + 1}}};
      for (const auto& t : {t1, t2}) {
        m.faces.push_back({id(t[0][0], t[0][1]), id(t[1][0], t[1][1]), id(t[2][0], t[2][1])});
        c.atlas.cornerUV.push_back({uv(t[0][0], t[0][1]), uv(t[1][0], t[1][1]), uv(t[2][0], t[2][1])});
        c.atlas.faceChart.push_back(chart);
      }
    }
  c.atlas.chartCount = charts;
  c.atlas.resolution = resolution;
  m.buildTopology();
  return c;
}

}  // namespace fgsg::rt::marching::testing
