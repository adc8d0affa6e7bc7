// A cell of a cellular texture (Legakis et al. 2001): a brick, a stone, an arch brick.
// A cell is a box in world space, or a clipped cell: the prism of a convex polygon (its
// `profile`) in the box's length-height plane, where a box would cross the face's outline
// or a claim (a rake, a hip, an arch's extrados). What it *claims* (the space no other
// cell may take, written into the occupancy maps) is the whole cell; what it *is* (the
// geometry that is output) is the cell shrunk by half a mortar joint on its sides, so
// neighbouring cells leave a joint for the mortar (§5 "Mortar").
#pragma once

#include "runtime/cells/convex_polygon.h"
#include "runtime/scope.h"

#include <algorithm>
#include <array>
#include <vector>

namespace fgsg::rt::cells {

// Which kind of base-mesh feature a cell was placed on (§4's order).
enum class FeatureKind : uint8_t { Corner, Edge, Face };

struct FeatureRef {
  FeatureKind kind = FeatureKind::Face;
  int index = -1;
};

// A mitre (docs/cells.md "Mitred cells"): the world half-space normal . x <= offset that
// a cell keeps where its face meets another face at a concave edge (a valley) and the two
// faces' layers of cells overlap: the plane halves their dihedral angle through the edge,
// so the cells of both faces meet on it at a diagonal. `normal` is unit.
struct MitreCut {
  Vec3 normal = Vec3::UnitX();
  double offset = 0;
};

struct Cell {
  Vec3 origin = Vec3::Zero();  // the box corner at (0, 0, 0)
  // Unit columns: axis 0 the cell's length (along the course), axis 1 its height,
  // axis 2 its depth (outward from the surface).
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Vec3 size = Vec3::Zero();
  FeatureRef feature;
  // A clipped cell's cross-section: convex, counter-clockwise, in (axis 0, axis 1)
  // coordinates from `origin`, its bounding rectangle [0, size.x] x [0, size.y]; the
  // cell is this polygon swept `size.z` along axis 2. Empty: the whole rectangle (a box).
  Polygon2 profile;
  // Mitres: the cell is its prism less the far side of each (a mitred cell always has a
  // profile, so it is never a box).
  std::vector<MitreCut> cuts;
  bool isBox() const { return profile.empty(); }
  // The profile, or the box's rectangle.
  Polygon2 outline() const {
    if (!isBox()) return profile;
    return {Vec2(0, 0), Vec2(size.x(), 0), Vec2(size.x(), size.y()), Vec2(0, size.y())};
  }
  // The area of the cross-section (the cell's share of its face, joints included).
  double area() const { return isBox() ? size.x() * size.y() : signedArea(profile); }
  // The cell's corners: the outline at depth 0, then at depth size.z.
  std::vector<Vec3> vertices() const {
    std::vector<Vec3> v;
    v.reserve(2 * (isBox() ? 4 : profile.size()));
    forEachVertex([&](const Vec3& p) { v.push_back(p); });
    return v;
  }
  // Calls visit(corner) for vertices() in their order, without allocating (the overlap
  // check's bounds).
  template <class Visit>
  void forEachVertex(Visit&& visit) const {
    const Vec2 rectangle[4] = {Vec2(0, 0), Vec2(size.x(), 0), Vec2(size.x(), size.y()), Vec2(0, size.y())};
    const Vec2* o = isBox() ? rectangle : profile.data();
    const size_t n = isBox() ? 4 : profile.size();
    for (double z : {0.0, size.z()})
      for (size_t k = 0; k < n; ++k) visit(Vec3(origin + axes.col(0) * o[k].x() + axes.col(1) * o[k].y() + axes.col(2) * z));
  }
  // The cell's solid as convex faces, counter-clockwise from outside: the prism of its
  // outline, less the far side of each mitre. (vertices() and forEachVertex() are the
  // prism's corners: bounds and claims on the cell's own face.)
  SolidFaces solid() const {
    std::vector<Vec3> bottom, top;
    forEachVertex([&](const Vec3& p) { (bottom.size() < (isBox() ? 4 : profile.size()) ? bottom : top).push_back(p); });
    SolidFaces f{top, std::vector<Vec3>(bottom.rbegin(), bottom.rend())};
    for (size_t i = 0; i < bottom.size(); ++i) {
      const size_t j = (i + 1) % bottom.size();
      f.push_back({bottom[i], bottom[j], top[j], top[i]});
    }
    if (axes.determinant() < 0)
      for (std::vector<Vec3>& face : f) std::reverse(face.begin(), face.end());
    const double tol = 1e-9 * std::max(1.0, size.maxCoeff());
    for (const MitreCut& m : cuts) f = clipSolid(f, m.normal, m.offset, tol);
    return f;
  }
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

// Makes a clipped cell's origin and size its profile's bounding box (the profile moved to
// start at (0, 0)); a box is left as it is.
inline void fitToProfile(Cell& c) {
  if (c.isBox()) return;
  Vec2 lo = c.profile[0], hi = c.profile[0];
  for (const Vec2& q : c.profile) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  for (Vec2& q : c.profile) q -= lo;
  c.origin += c.axes.col(0) * lo.x() + c.axes.col(1) * lo.y();
  c.size.x() = hi.x() - lo.x(), c.size.y() = hi.y() - lo.y();
}

// The cell as it is output: shrunk by joint / 2 on axes 0 and 1 (never below a tenth of
// its size), depth kept. A clipped cell's sides each move joint / 2 inwards (less where
// that would leave under a tenth of its area), and so does each mitre.
inline Cell shrunk(const Cell& c, double joint) {
  if (!c.isBox()) {
    const double area = c.area();
    for (double by = 0.5 * joint; by > 1e-6 * joint; by *= 0.5) {
      Polygon2 in = insetConvex(c.profile, by);
      if (in.empty() || signedArea(in) < 0.1 * area) continue;
      Cell s = c;
      s.profile = std::move(in);
      fitToProfile(s);
      for (MitreCut& m : s.cuts) m.offset -= by;  // the joint along the mitre too
      return s;
    }
    return c;
  }
  Cell s = c;
  for (int k = 0; k < 2; ++k) {
    const double cut = std::min(joint, 0.9 * c.size[k]);
    s.origin += c.axes.col(k) * (0.5 * cut);
    s.size[k] -= cut;
  }
  return s;
}

}  // namespace fgsg::rt::cells
