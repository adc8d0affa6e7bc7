// Painting a texture context without a paint program: a mask image in the surface's
// texture coordinates (MarchingSurface::texCoord, what `context.NAME(texCoord)` samples),
// white where the surface lies inside any of a set of brushes (spheres, slabs) and black
// elsewhere. `fgsg atlas --paint` writes one; the examples' masks are made so, and a
// test repaints them to catch an atlas change that would leave them stale.
#pragma once

#include "runtime/marching/marching_surface.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::texture {

// A sphere (the surface within `radius` of `centre`), or with `slab` set a band: the
// surface within `radius` of the plane through `centre` square to `normal` (a painted
// stroke around a body).
struct Brush {
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
  bool slab = false;
  Vec3 normal = Vec3::UnitZ();  // unit
  bool covers(const Vec3& p) const {
    return slab ? std::abs(normal.dot(p - centre)) <= radius : (p - centre).norm() <= radius;
  }
};

struct MaskImage {
  int size = 0;                 // width = height
  std::vector<uint8_t> grey;    // rows top to bottom (v = 1 at row 0), 0 or 255
};

// Every pixel whose centre lies in a face's texture triangle is white when that surface
// point is inside a brush; pixels outside every triangle then take the brightest of their
// covered neighbours, twice over, so bilinear sampling at a chart's edge reads the chart.
MaskImage paintMask(const marching::MarchingSurface& surface, int size, const std::vector<Brush>& brushes);

// The mask as an 8-bit grey PNG, written atomically; false with a message.
bool writeMaskPng(const MaskImage& mask, const std::string& path, std::string& error);

}  // namespace fgsg::rt::texture
