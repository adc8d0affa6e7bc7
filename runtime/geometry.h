// The geometry a shape carries besides its scope box, kept in one arena per derivation
// so shapes hold only a small reference (no per-shape heap allocation). Coordinates are
// normalised to the scope: (0,0,0)..(1,1,1) spans the scope box, so scaling the scope
// with S() scales the geometry with it. A dimension of size zero keeps coordinate 0.
#pragma once

#include "runtime/scope.h"

#include <cstdint>
#include <vector>

namespace fgsg::rt {

enum class GeomKind : uint8_t {
  Box,         // the scope box itself (the default for every shape)
  Polygon,     // a planar polygon in the scope's XY plane (z = 0), counter-clockwise
               // seen from +Z; Z is its outward normal
  Polyhedron,  // closed set of planar faces (an extruded footprint, a roof)
  Edge,        // a segment along the scope's Y axis from (0,0,0) to (0,1,0)
};

struct GeomRef {
  GeomKind kind = GeomKind::Box;
  uint32_t first = 0;  // Polygon: first point; Polyhedron: first face
  uint32_t count = 0;  // Polygon: point count; Polyhedron: face count
};

class GeometryArena {
 public:
  struct Face {
    uint32_t first = 0;  // into points
    uint32_t count = 0;
  };

  GeomRef addPolygon(const std::vector<Vec3>& pts) {
    GeomRef r{GeomKind::Polygon, static_cast<uint32_t>(points_.size()),
              static_cast<uint32_t>(pts.size())};
    points_.insert(points_.end(), pts.begin(), pts.end());
    return r;
  }
  GeomRef addPolyhedron(const std::vector<std::vector<Vec3>>& faces) {
    GeomRef r{GeomKind::Polyhedron, static_cast<uint32_t>(faces_.size()),
              static_cast<uint32_t>(faces.size())};
    for (const auto& f : faces) {
      faces_.push_back({static_cast<uint32_t>(points_.size()), static_cast<uint32_t>(f.size())});
      points_.insert(points_.end(), f.begin(), f.end());
    }
    return r;
  }
  const Vec3* polygon(const GeomRef& r) const { return points_.data() + r.first; }
  const Face& face(const GeomRef& r, uint32_t i) const { return faces_[r.first + i]; }
  const Vec3* facePoints(const Face& f) const { return points_.data() + f.first; }
  void clear() {
    points_.clear();
    faces_.clear();
  }

 private:
  std::vector<Vec3> points_;
  std::vector<Face> faces_;
};

}  // namespace fgsg::rt
