// Small planar helpers shared by the runtime's 2D checks: chart boundaries in texture
// space, footprint polygons, GIS lots.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace fgsg::rt {

// Twice the signed area of triangle (a, b, c): positive when it runs counter-clockwise.
inline double twiceSignedArea(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Twice the signed area of a ring (positive counter-clockwise), summed about its first
// point for precision far from the origin.
inline double twiceRingArea(const std::vector<Eigen::Vector2d>& ring) {
  double sum = 0;
  for (size_t i = 1; i + 1 < ring.size(); ++i) sum += twiceSignedArea(ring[0], ring[i], ring[i + 1]);
  return sum;
}

// Whether closed segments pq and rs share a point (touching counts).
inline bool segmentsMeet(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r,
                         const Eigen::Vector2d& s) {
  const double o1 = twiceSignedArea(p, q, r), o2 = twiceSignedArea(p, q, s);
  const double o3 = twiceSignedArea(r, s, p), o4 = twiceSignedArea(r, s, q);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  // Touching: an end on the other segment.
  auto within = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {  // c on line ab
    return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= c.y() &&
           c.y() <= std::max(a.y(), b.y());
  };
  return (o1 == 0 && within(p, q, r)) || (o2 == 0 && within(p, q, s)) || (o3 == 0 && within(r, s, p)) ||
         (o4 == 0 && within(r, s, q));
}

}  // namespace fgsg::rt
