#include "runtime/marching/image_triangles.h"

#include "runtime/surface/locate.h"

#include <Eigen/LU>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace fgsg::rt::marching {

namespace {

// Shared corners closer than this (texels) are the same image point: an atlas stores
// each vertex's coordinates once per face, so a chart's own edges match to the last bit
// or nearly; a seam's two sides are whole texels apart.
constexpr double kSameCornerTexels = 1e-6;
// A UV triangle whose doubled area is below this fraction of its longest edge squared
// is degenerate (as load_surface.h's kDegenerateFaceTolerance for 3D faces).
constexpr double kDegenerateTolerance = 1e-10;
// Coordinates may stray this far outside [0, 1] by rounding.
constexpr double kUnitSquareSlack = 1e-9;

// What can be wrong with a face of an atlas.
enum Problem : uint8_t { kFine, kChart, kOutside, kDegenerate, kMirrored, kFlat3D };

// Fills t for face f and says what is wrong with it.
uint8_t describeFace(const surface::SurfaceMesh& mesh, const atlas::Atlas& atlas, size_t f, ImageTriangle& t) {
  const double n = atlas.resolution;
  t.chart = atlas.faceChart[f];
  if (t.chart < 0 || t.chart >= atlas.chartCount) return kChart;
  for (int k = 0; k < 3; ++k) {
    const Vec2& uv = atlas.cornerUV[f][k];
    if (!uv.allFinite() || uv.minCoeff() < -kUnitSquareSlack || uv.maxCoeff() > 1 + kUnitSquareSlack) return kOutside;
    t.corner[k] = uv.cwiseMax(0.0).cwiseMin(1.0) * n;
  }
  Eigen::Matrix2d edges;
  edges << t.corner[1] - t.corner[0], t.corner[2] - t.corner[0];
  const double doubledArea = edges.determinant();
  const double longest = std::max({edges.col(0).squaredNorm(), edges.col(1).squaredNorm(),
                                   (t.corner[2] - t.corner[1]).squaredNorm()});
  if (!(std::abs(doubledArea) > kDegenerateTolerance * longest)) return kDegenerate;
  if (doubledArea < 0) return kMirrored;
  if (!(mesh.faceAreas[f] > 0)) return kFlat3D;
  const auto& v = mesh.faces[f];
  Eigen::Matrix<double, 3, 2> edges3;
  edges3 << mesh.vertices[v[1]] - mesh.vertices[v[0]], mesh.vertices[v[2]] - mesh.vertices[v[0]];
  t.toBary = edges.inverse();
  t.toSurface = edges3 * t.toBary;
  const Eigen::Matrix2d gram = t.toSurface.transpose() * t.toSurface;
  t.toImage = gram.inverse() * t.toSurface.transpose();
  // The largest eigenvalue of the 2x2 metric: the longest 3D stretch of a unit image step.
  const double half = 0.5 * gram.trace();
  const double gap = std::sqrt(std::max(0.0, half * half - gram.determinant()));
  t.texelLength = std::sqrt(half + gap);
  return kFine;
}

std::string faceName(size_t f) { return "face " + std::to_string(f); }

}  // namespace

Vec3 ImageTriangle::closestBary(const Vec2& x) const {
  const Vec3 inside = baryOf(x);
  if (inside.minCoeff() >= 0) return inside;
  auto lift = [](const Vec2& p) { return Vec3(p[0], p[1], 0); };
  Vec3 bary;
  surface::closestPointOnTriangle(lift(x), lift(corner[0]), lift(corner[1]), lift(corner[2]), bary);
  return bary;
}

bool buildImageTriangles(const surface::SurfaceMesh& mesh, const atlas::Atlas& atlas,
                         std::vector<ImageTriangle>& out, std::string& error) {
  const size_t nf = mesh.faceCount();
  if (mesh.neighbours.size() != nf || mesh.faceNormals.size() != nf) {
    error = "the surface's topology is not built";
    return false;
  }
  if (atlas.faceChart.size() != nf || atlas.cornerUV.size() != nf) {
    error = "the atlas has " + std::to_string(atlas.faceChart.size()) + " faces, the surface " +
            std::to_string(nf);
    return false;
  }
  if (atlas.chartCount <= 0) {
    error = "the atlas has no charts";
    return false;
  }
  const int n = atlas.resolution;
  if (n < kMinImageResolution || n > kMaxImageResolution) {
    error = "the atlas resolution " + std::to_string(n) + " is out of range (" +
            std::to_string(kMinImageResolution) + ".." + std::to_string(kMaxImageResolution) + ")";
    return false;
  }
  out.assign(nf, ImageTriangle{});
  // Faces are independent: each records what is wrong with it, and the lowest such face
  // is reported, as a serial pass would.
  std::vector<uint8_t> problem(nf, kFine);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nf, 1024), [&](const auto& range) {
    for (size_t f = range.begin(); f < range.end(); ++f) problem[f] = describeFace(mesh, atlas, f, out[f]);
  });
  for (size_t f = 0; f < nf; ++f) {
    switch (problem[f]) {
      case kFine: continue;
      case kChart:
        error = faceName(f) + " has chart " + std::to_string(atlas.faceChart[f]) + ", not one of the atlas's " +
                std::to_string(atlas.chartCount);
        return false;
      case kOutside: error = faceName(f) + " has texture coordinates outside the unit square"; return false;
      case kDegenerate: error = faceName(f) + " is degenerate in the atlas (zero area)"; return false;
      case kMirrored:
        error = faceName(f) + " is mirrored in the atlas (clockwise, the surface is counter-clockwise)";
        return false;
      default: error = faceName(f) + " has zero area on the surface"; return false;
    }
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nf, 1024), [&](const auto& range) {
    for (size_t f = range.begin(); f < range.end(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int g = mesh.neighbours[f][k];
        if (g < 0 || out[g].chart != out[f].chart) continue;
        const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
        const int ga = mesh.cornerOf(g, a), gb = mesh.cornerOf(g, b);
        if (ga < 0 || gb < 0) continue;
        if ((out[g].corner[ga] - out[f].corner[k]).norm() <= kSameCornerTexels &&
            (out[g].corner[gb] - out[f].corner[(k + 1) % 3]).norm() <= kSameCornerTexels)
          out[f].continuation[k] = g;
      }
  });
  return true;
}

}  // namespace fgsg::rt::marching
