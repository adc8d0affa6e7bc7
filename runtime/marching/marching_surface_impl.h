// What a MarchingSurface holds, shared by the files of runtime/marching that implement it
// (not included from outside this folder).
#pragma once

#include "runtime/marching/chart_walk.h"
#include "runtime/marching/geometry_image.h"
#include "runtime/marching/image_triangles.h"
#include "runtime/marching/marching_surface.h"

#include <vector>

namespace fgsg::rt::marching {

struct MarchingSurface::Impl {
  surface::SurfaceMesh mesh;
  atlas::Atlas atlas;
  MarchingOptions options;
  std::vector<ImageTriangle> triangles;
  GeometryImage image;
  // A landing this close (3D) to the exit point is the same point: rounding apart, both
  // sides of a seam share its vertices (1e-9 of the surface's size).
  double landingTolerance = 0;
};

// Where a march continues after leaving its chart through edge `edge` of face f at
// `bary` heading along image direction d (§5 cases B-D): the landing point in the next
// chart and the direction there. False at the surface's own boundary.
struct SeamJump {
  ChartPoint landing;
  Vec2 dir;
  bool viaPointer = false;
};
bool jumpAcrossSeam(const MarchingSurface::Impl& s, int f, int edge, const Vec3& bary, const Vec2& d, SeamJump& out);

}  // namespace fgsg::rt::marching
