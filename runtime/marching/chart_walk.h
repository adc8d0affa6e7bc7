// Straight lines in a chart's image, followed face by face. Inside a chart the image is a
// flat triangulation and a face maps affinely onto its 3D triangle, so a point kept as
// (face, barycentric coordinates) while moving along an image line is an exact surface
// point at every step; neighbours that continue the chart (ImageTriangle::continuation)
// hand the point on by their shared vertices, never by recomputed coordinates.
#pragma once

#include "runtime/marching/image_triangles.h"
#include "runtime/surface/surface_mesh.h"

#include <vector>

namespace fgsg::rt::marching {

struct ChartPoint {
  int face = -1;
  Vec3 bary = Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3);
};

// Where the image line from `bary` along image direction d leaves its face: after
// `length` texels, through edge `edge` (corner edge to edge + 1), opposite corner
// `corner`. At a vertex the line may leave at once (length 0) through the edge it
// crosses fastest, which turns it around the vertex towards the face it enters.
struct FaceExit {
  double length = 0;
  int edge = -1;
  int corner = -1;
};
FaceExit faceExit(const ImageTriangle& t, const Vec3& bary, const Vec2& d);

// The point on edge `edge` of face f (its coordinate opposite the edge zero) as seen
// from face g across that edge.
Vec3 baryAcross(const surface::SurfaceMesh& mesh, int f, int edge, const Vec3& bary, int g);

// Clamps rounding out of barycentric coordinates: non-negative, summing to 1.
Vec3 tidyBary(const Vec3& bary);

// Walks straight from p to image point x inside p's chart. True with p at x; false when
// the chart's border (a seam or the surface's boundary) comes first, p then stopping on
// it, or when the walk cannot progress within the face budget.
bool walkTo(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles, ChartPoint& p,
            const Vec2& x);

// The point of `start`'s chart closest in 3D to P, searched from face `start` over the
// faces that continue it, nearest first, among those no more than 1.5 times as far
// from P as the start (at most 256 faces). True when within `tolerance` of P.
bool landNear(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles, int start,
              const Vec3& P, double tolerance, ChartPoint& out);

inline Vec3 surfacePoint(const surface::SurfaceMesh& mesh, const ChartPoint& p) {
  const auto& v = mesh.faces[p.face];
  return p.bary[0] * mesh.vertices[v[0]] + p.bary[1] * mesh.vertices[v[1]] + p.bary[2] * mesh.vertices[v[2]];
}

}  // namespace fgsg::rt::marching
