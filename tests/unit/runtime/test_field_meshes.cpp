// Small meshes for the field tests, built here so the tests depend on nothing but the
// mesh type: a flat grid, an icosphere, a torus grid and an open cylinder. Declared in
// each test_field_*.cpp that uses them.
#include "runtime/surface/surface_mesh.h"

#include <cmath>
#include <map>
#include <utility>

namespace fgsg::rt::field::testing {

using surface::SurfaceMesh;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Makes every face's normal agree with `outward` at its centroid (generators below build
// consistently oriented grids, so flipping all faces when the first disagrees suffices).
template <class Outward>
void orient(SurfaceMesh& m, Outward outward) {
  const auto& t = m.faces[0];
  const Vec3 c = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3;
  const Vec3 n = (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
  if (n.dot(outward(c)) < 0)
    for (auto& f : m.faces) std::swap(f[1], f[2]);
}

}  // namespace

// nx x ny quads in [x0, x0 + w] x [y0, y0 + h] (z = 0), split along alternating
// diagonals; `jitter` moves interior vertices by up to that fraction of a cell.
SurfaceMesh flatGrid(int nx, int ny, double x0, double y0, double w, double h, double jitter) {
  SurfaceMesh m;
  uint32_t seed = 12345;
  auto rnd = [&] {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / double(1 << 24) - 0.5;
  };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      Vec3 p(x0 + w * i / nx, y0 + h * j / ny, 0);
      if (i > 0 && i < nx && j > 0 && j < ny) {
        p.x() += jitter * w / nx * rnd();
        p.y() += jitter * h / ny * rnd();
      }
      m.vertices.push_back(p);
    }
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      } else {
        m.faces.push_back({a, b, d});
        m.faces.push_back({b, c, d});
      }
    }
  m.buildTopology();
  return m;
}

SurfaceMesh icosphere(int subdivisions, double radius) {
  SurfaceMesh m;
  const double t = (1 + std::sqrt(5.0)) / 2;
  m.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  m.faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
             {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (auto& v : m.vertices) v.normalize();
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      return mid[key] = int(m.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> faces;
    for (const auto& f : m.faces) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      faces.push_back({f[0], ab, ca});
      faces.push_back({f[1], bc, ab});
      faces.push_back({f[2], ca, bc});
      faces.push_back({ab, bc, ca});
    }
    m.faces = std::move(faces);
  }
  for (auto& v : m.vertices) v *= radius;
  orient(m, [](const Vec3& c) { return Vec3(c); });
  m.buildTopology();
  return m;
}

// A torus around Z: nu segments around the axis, nv around the tube.
SurfaceMesh torus(int nu, int nv, double R, double r) {
  SurfaceMesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
      m.vertices.push_back({(R + r * std::cos(v)) * std::cos(u),
                            (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      m.faces.push_back({a, b, c});
      m.faces.push_back({a, c, d});
    }
  orient(m, [R](const Vec3& c) {
    const Vec3 axis = Vec3(c.x(), c.y(), 0).normalized() * R;
    return Vec3(c - axis);
  });
  m.buildTopology();
  return m;
}

// An open cylinder around Z: radius r, height h from z = 0.
SurfaceMesh cylinder(int nu, int nz, double r, double h) {
  SurfaceMesh m;
  for (int j = 0; j <= nz; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * kPi * (i + 0.5 * (j % 2)) / nu;
      m.vertices.push_back({r * std::cos(u), r * std::sin(u), h * j / nz});
    }
  auto id = [&](int i, int j) { return j * nu + (i + nu) % nu; };
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      m.faces.push_back({a, b, c});
      m.faces.push_back({a, c, d});
    }
  orient(m, [](const Vec3& c) { return Vec3(c.x(), c.y(), 0); });
  m.buildTopology();
  return m;
}

}  // namespace fgsg::rt::field::testing
