// A cell of a cellular texture (Legakis et al. 2001): a brick, a stone, an arch brick.
// Every cell is a box in world space: what it *claims* (the space no other cell may
// take, written into the occupancy maps) is the whole box; what it *is* (the geometry
// that is output) is the box shrunk by half a mortar joint on its two face-parallel
// axes, so neighbouring cells leave a joint for the mortar (§5 "Mortar").
#pragma once

#include "runtime/scope.h"

#include <array>

namespace fgsg::rt::cells {

// Which kind of base-mesh feature a cell was placed on (§4's order).
enum class FeatureKind : uint8_t { Corner, Edge, Face };

struct FeatureRef {
  FeatureKind kind = FeatureKind::Face;
  int index = -1;
};

struct Cell {
  Vec3 origin = Vec3::Zero();  // the box corner at (0, 0, 0)
  // Unit columns: axis 0 the cell's length (along the course), axis 1 its height,
  // axis 2 its depth (outward from the surface).
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Vec3 size = Vec3::Zero();
  FeatureRef feature;
  // The box's corner k (bit 0: +length, bit 1: +height, bit 2: +depth).
  Vec3 corner(int k) const {
    return origin + axes.col(0) * ((k & 1) ? size.x() : 0.0) + axes.col(1) * ((k & 2) ? size.y() : 0.0) +
           axes.col(2) * ((k & 4) ? size.z() : 0.0);
  }
  std::array<Vec3, 8> corners() const {
    std::array<Vec3, 8> c;
    for (int k = 0; k < 8; ++k) c[k] = corner(k);
    return c;
  }
  Vec3 centre() const { return origin + axes * (0.5 * size); }
};

// The cell as it is output: shrunk by joint / 2 on axes 0 and 1 (never below a tenth of
// its size), depth kept.
inline Cell shrunk(const Cell& c, double joint) {
  Cell s = c;
  for (int k = 0; k < 2; ++k) {
    const double cut = std::min(joint, 0.9 * c.size[k]);
    s.origin += c.axes.col(k) * (0.5 * cut);
    s.size[k] -= cut;
  }
  return s;
}

}  // namespace fgsg::rt::cells
