// What every atlas must satisfy, checked independently of how it was built: used by the
// atlas tests on generated and file layouts alike.
#pragma once

#include "runtime/atlas/atlas.h"
#include "runtime/surface/load_surface.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace fgsg::test {

using rt::atlas::Atlas;
using rt::atlas::Vec2;

inline double twiceSignedArea(const std::array<Vec2, 3>& t) {
  return (t[1].x() - t[0].x()) * (t[2].y() - t[0].y()) - (t[1].y() - t[0].y()) * (t[2].x() - t[0].x());
}

// A mesh of tests/data/meshes, loaded as `fgsg run --surface` does.
inline rt::surface::SurfaceMesh loadTestMesh(const std::string& name) {
  rt::surface::SurfaceMesh mesh;
  std::string error;
  const std::string path = std::string(FGSG_SOURCE_DIR) + "/tests/data/meshes/" + name;
  INFO(error);
  REQUIRE(rt::surface::loadSurface(path, mesh, error));
  return mesh;
}

// Whether the closed texel square [x, x+1] x [y, y+1] (texel units) meets triangle t.
inline bool texelMeetsTriangle(int x, int y, const std::array<Vec2, 3>& t) {
  const Vec2 square[4] = {Vec2(x, y), Vec2(x + 1, y), Vec2(x + 1, y + 1), Vec2(x, y + 1)};
  std::vector<Vec2> axes = {Vec2(1, 0), Vec2(0, 1)};
  for (int k = 0; k < 3; ++k) {
    const Vec2 e = t[(k + 1) % 3] - t[k];
    axes.emplace_back(-e.y(), e.x());
  }
  for (const Vec2& a : axes) {
    double sLo = INFINITY, sHi = -INFINITY, tLo = INFINITY, tHi = -INFINITY;
    for (const Vec2& p : square) sLo = std::min(sLo, a.dot(p)), sHi = std::max(sHi, a.dot(p));
    for (const Vec2& p : t) tLo = std::min(tLo, a.dot(p)), tHi = std::max(tHi, a.dot(p));
    if (sHi < tLo || tHi < sLo) return false;
  }
  return true;
}

// Every chart as the texels it touches (conservatively: any texel whose closed square
// meets one of its triangles), as a resolution^2 grid of chart ids (-1: empty). Two
// charts on one texel fail at once.
inline std::vector<int> rasterizeCharts(const Atlas& atlas) {
  const int r = atlas.resolution;
  std::vector<int> grid(size_t(r) * r, -1);
  for (size_t f = 0; f < atlas.cornerUV.size(); ++f) {
    std::array<Vec2, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = atlas.cornerUV[f][k] * r;
    const Vec2 lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]), hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
    for (int y = std::max(0, int(std::floor(lo.y())) - 1); y <= std::min(r - 1, int(hi.y()) + 1); ++y)
      for (int x = std::max(0, int(std::floor(lo.x())) - 1); x <= std::min(r - 1, int(hi.x()) + 1); ++x) {
        if (!texelMeetsTriangle(x, y, t)) continue;
        int& cell = grid[size_t(y) * r + x];
        if (cell >= 0 && cell != atlas.faceChart[f]) {
          FAIL("charts " << cell << " and " << atlas.faceChart[f] << " share texel (" << x << ", " << y
                         << "), at face " << f);
        }
        cell = atlas.faceChart[f];
      }
  }
  return grid;
}

struct AtlasFigures {
  std::vector<double> density;   // per chart: UV area / surface area
  double meanStretch = 0;        // area-weighted mean of sigma_max / sigma_min (1: conformal)
  double maxStretch = 0;
  double coverage = 0;           // UV area of all charts / the unit square
};

// The structural guarantees of an atlas of `mesh` packed with `gutter` texels: every face
// in a chart, corners inside the border, no triangle flipped or collapsed, and no texel
// of one chart within `gutter` texels (in x or y) of a texel of another or of the image's
// edge. Returns the figures the callers bound.
inline AtlasFigures checkAtlas(const rt::surface::SurfaceMesh& mesh, const Atlas& atlas, int gutter) {
  const size_t nf = mesh.faces.size();
  REQUIRE(atlas.faceChart.size() == nf);
  REQUIRE(atlas.cornerUV.size() == nf);
  REQUIRE(atlas.chartCount >= 1);
  const int r = atlas.resolution;
  std::vector<double> uvArea(atlas.chartCount, 0), surfaceArea(atlas.chartCount, 0);
  AtlasFigures figures;
  double stretchSum = 0, areaSum = 0;
  for (size_t f = 0; f < nf; ++f) {
    const int c = atlas.faceChart[f];
    REQUIRE(c >= 0);
    REQUIRE(c < atlas.chartCount);
    for (const Vec2& p : atlas.cornerUV[f]) {
      INFO("face " << f << " corner (" << p.x() << ", " << p.y() << ")");
      REQUIRE(p.allFinite());
      REQUIRE(p.minCoeff() >= double(gutter) / r);
      REQUIRE(p.maxCoeff() <= 1.0 - double(gutter) / r);
    }
    const double uv = 0.5 * twiceSignedArea(atlas.cornerUV[f]);
    INFO("face " << f << " has UV area " << uv);
    REQUIRE(uv > 0);  // neither flipped nor collapsed
    uvArea[c] += uv;
    const auto& t = mesh.faces[f];
    const rt::Vec3 p = mesh.vertices[t[0]], e1 = mesh.vertices[t[1]] - p, e2 = mesh.vertices[t[2]] - p;
    surfaceArea[c] += mesh.faceAreas[f];
    // The map from the triangle's own plane to UV: its singular values' ratio.
    const rt::Vec3 x = e1.normalized(), y = e1.cross(e2).cross(e1).normalized();
    Eigen::Matrix2d flat, image;
    flat << e1.dot(x), e2.dot(x), e1.dot(y), e2.dot(y);
    const auto& q = atlas.cornerUV[f];
    image << (q[1] - q[0]).x(), (q[2] - q[0]).x(), (q[1] - q[0]).y(), (q[2] - q[0]).y();
    const Eigen::Vector2d s = Eigen::JacobiSVD<Eigen::Matrix2d>(image * flat.inverse()).singularValues();
    const double stretch = s[0] / s[1];
    stretchSum += stretch * mesh.faceAreas[f];
    areaSum += mesh.faceAreas[f];
    figures.maxStretch = std::max(figures.maxStretch, stretch);
    figures.coverage += uv;
  }
  figures.meanStretch = stretchSum / areaSum;
  for (int c = 0; c < atlas.chartCount; ++c) {
    INFO("chart " << c);
    REQUIRE(surfaceArea[c] > 0);  // no chart is empty
    figures.density.push_back(uvArea[c] / surfaceArea[c]);
  }

  const std::vector<int> grid = rasterizeCharts(atlas);
  for (int y = 0; y < r; ++y)
    for (int x = 0; x < r; ++x) {
      const int c = grid[size_t(y) * r + x];
      if (c < 0) continue;
      INFO("chart " << c << " at texel (" << x << ", " << y << ")");
      REQUIRE(x >= gutter);
      REQUIRE(y >= gutter);
      REQUIRE(x < r - gutter);
      REQUIRE(y < r - gutter);
      for (int dy = -gutter; dy <= gutter; ++dy)
        for (int dx = -gutter; dx <= gutter; ++dx) {
          const int other = grid[size_t(y + dy) * r + (x + dx)];
          if (other >= 0 && other != c)
            FAIL("charts " << c << " and " << other << " are closer than the gutter at texel (" << x
                           << ", " << y << ")");
        }
    }
  return figures;
}

}  // namespace fgsg::test
