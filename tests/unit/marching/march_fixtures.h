// What the march tests share: a prepared surface over a hand-laid atlas, and the checks
// every march result must pass.
#pragma once

#include "charted_shapes.h"

#include "runtime/marching/geometry_image.h"
#include "runtime/marching/marching_surface.h"
#include "runtime/surface/locate.h"

#include <catch2/catch.hpp>

#include <memory>

namespace fgsg::rt::marching::testing {

inline std::shared_ptr<const MarchingSurface> prepared(const ChartedMesh& c) {
  std::string error;
  auto s = MarchingSurface::fromAtlas(c.mesh, c.atlas, MarchingOptions{}, error);
  INFO(error);
  REQUIRE(s);
  return s;
}

// The march point at the surface point closest to p, heading along dir3.
inline MarchPoint placeAt(const MarchingSurface& s, const Vec3& p, const Vec3& dir3) {
  return s.place(surface::closestPoint(s.mesh(), p), dir3);
}

// A march point is whole: a face, barycentric coordinates of a point in it, its image
// position that point's, its chart the face's, a unit direction.
inline bool consistent(const MarchingSurface& s, const MarchPoint& p) {
  if (p.at.face < 0 || p.at.face >= int(s.mesh().faceCount())) return false;
  if (p.at.bary.minCoeff() < 0 || std::abs(p.at.bary.sum() - 1) > 1e-12) return false;
  const auto& uv = s.atlas().cornerUV[p.at.face];
  const Vec2 image = (p.at.bary[0] * uv[0] + p.at.bary[1] * uv[1] + p.at.bary[2] * uv[2]) * s.atlas().resolution;
  const int n = s.atlas().resolution;
  return (image - p.image).norm() < 1e-9 && p.image.minCoeff() >= 0 && p.image.maxCoeff() <= n &&
         p.chart == s.atlas().faceChart[p.at.face] && std::abs(p.dir.norm() - 1) < 1e-12;
}

}  // namespace fgsg::rt::marching::testing
