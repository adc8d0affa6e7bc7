#pragma once
// An axis-aligned box as a closed surface mesh, the test input of the poly-cube map, the
// surface ornament and their stretch and variation tests.
#include "runtime/surface/surface_mesh.h"

namespace fgsg::test {

// Each side of the box as a quad of corner indices (corner i has x from bit 0, y from bit
// 1, z from bit 2), counter-clockwise seen from outside.
constexpr int kBoxSideQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

// The box from lo to hi, two triangles per side, counter-clockwise from outside.
inline rt::surface::SurfaceMesh boxSurface(const rt::Vec3& lo, const rt::Vec3& hi) {
  rt::surface::SurfaceMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back(rt::Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
  for (const auto& q : kBoxSideQuads) {
    m.faces.push_back({q[0], q[1], q[2]});
    m.faces.push_back({q[0], q[2], q[3]});
  }
  m.buildTopology();
  return m;
}

}  // namespace fgsg::test
