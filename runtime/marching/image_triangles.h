// The mesh's faces as the geometry image sees them: each face's corners in image units
// (texels), the affine maps between its image triangle and its 3D triangle, and which of
// its neighbours continue it without a seam. Marching walks straight lines across these
// flat triangles, so every point it reaches is an exact surface point.
#pragma once

#include "runtime/atlas/atlas.h"
#include "runtime/surface/surface_mesh.h"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace fgsg::rt::marching {

using atlas::Vec2;

struct ImageTriangle {
  std::array<Vec2, 3> corner;                // the face's corners in the image, texels (y up)
  Eigen::Matrix2d toBary;                    // image offset from corner 0 -> (b1, b2)
  Eigen::Matrix<double, 3, 2> toSurface;     // image displacement -> 3D displacement
  Eigen::Matrix<double, 2, 3> toImage;       // 3D displacement in the face's plane -> image
  // Across edge k (corner k to corner k+1): the neighbour that continues this face in the
  // image (same chart, same image corners on the shared edge), or -1 at a seam or at the
  // surface's own boundary.
  std::array<int, 3> continuation{-1, -1, -1};
  int chart = -1;
  double texelLength = 0;  // the longest 3D length one texel spans in this face

  Vec2 imagePoint(const Vec3& bary) const {
    return bary[0] * corner[0] + bary[1] * corner[1] + bary[2] * corner[2];
  }
  // Barycentric coordinates of an image point (outside the triangle: some negative).
  Vec3 baryOf(const Vec2& x) const {
    const Vec2 b = toBary * (x - corner[0]);
    return Vec3(1 - b[0] - b[1], b[0], b[1]);
  }
  // The barycentric coordinates of the point of this triangle closest to image point x
  // (x itself when inside).
  Vec3 closestBary(const Vec2& x) const;
  // How barycentric coordinates change per texel moved along image direction d.
  Vec3 baryRate(const Vec2& d) const {
    const Vec2 b = toBary * d;
    return Vec3(-b[0] - b[1], b[0], b[1]);
  }
};

// Geometry images larger than this per side would need gigabytes.
constexpr int kMaxImageResolution = 8192;
constexpr int kMinImageResolution = 8;

// One ImageTriangle per face of `mesh` (whose topology must be built), laid out by
// `atlas` at atlas.resolution texels per side. False with a message naming the first
// offending face when the atlas does not fit the mesh, leaves the unit square, or has a
// degenerate or mirrored triangle (marching's direction maps need both orientations to
// agree).
bool buildImageTriangles(const surface::SurfaceMesh& mesh, const atlas::Atlas& atlas,
                         std::vector<ImageTriangle>& out, std::string& error);

}  // namespace fgsg::rt::marching
