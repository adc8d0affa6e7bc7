// Offset: a polygon's inside, set back from its edges by a distance, and the border band
// that is left (CGA's offset / setback), by CGAL's interior straight-skeleton offsets.
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/skeleton_roof.h"
#include "runtime/abandonable.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/create_offset_polygons_from_polygon_with_holes_2.h>

#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polygon2 = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles2 = CGAL::Polygon_with_holes_2<Kernel>;

// A ring in scope units of the polygon's plane (x along X, y along Y), counter-clockwise
// for an outline, clockwise for a hole.
Polygon2 toCgal(const Polygon3& ring, const Vec3& size, bool hole) {
  Polygon2 p;
  for (const Vec3& q : ring) p.push_back(Kernel::Point_2(q.x() * size.x(), q.y() * size.y()));
  if (p.is_counterclockwise_oriented() == hole) p.reverse_orientation();
  return p;
}

std::vector<Vec2> toPoints(const Polygon2& p) {
  std::vector<Vec2> pts;
  for (const auto& q : p.vertices()) pts.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  return pts;
}

// An outline with holes as one bridged polygon in the scope's normalised coordinates.
bool store(const std::vector<Vec2>& outline, const std::vector<std::vector<Vec2>>& holes, const Vec3& size,
           GeometryArena& arena, GeomRef& out, std::string& error) {
  std::vector<Vec2> ring = outline;
  if (!holes.empty() && !joinHolesInPlane(outline, holes, "Offset: ", ring, error)) return false;
  Polygon3 normalised;
  for (const Vec2& p : ring) normalised.emplace_back(p.x() / size.x(), p.y() / size.y(), 0.0);
  if (newellNormal(normalised).z() < 0) std::reverse(normalised.begin(), normalised.end());
  out = arena.addPolygon(normalised);
  return true;
}

}  // namespace

bool offset(const Scope& scope, const GeomRef& geom, double distance, bool wantBorder, GeometryArena& arena,
            std::vector<Part>& inside, std::vector<Part>& border, std::string& error, const Deadline* deadline) {
  inside.clear();
  border.clear();
  if (!(distance > 0.0) || !std::isfinite(distance)) {
    std::ostringstream m;
    m << "Offset: the distance " << distance << " must be positive";
    error = m.str();
    return false;
  }
  Scope planar = scope;
  GeomRef polygon = geom;
  if (geom.kind == GeomKind::Box && scope.S.y() == 0.0 && scope.S.x() > 0.0 && scope.S.z() > 0.0) {
    // A footprint S(w, 0, d): its rectangle as the polygon Footprint makes.
    Part part;
    if (!footprint(scope, {{0, 0}, {scope.S.x(), 0}, {scope.S.x(), scope.S.z()}, {0, scope.S.z()}}, {}, arena, part,
                   error))
      return false;
    planar = part.scope;
    polygon = part.geom;
  } else if (geom.kind != GeomKind::Polygon || !(scope.S.x() > 0.0 && scope.S.y() > 0.0)) {
    error = "Offset: expects a polygon (a Footprint, a lot, a Comp face) or a flat footprint S(w, 0, d)";
    return false;
  }
  const Polygon3 pts(arena.polygon(polygon), arena.polygon(polygon) + polygon.count);
  const std::vector<Polygon3> rings = ringsOf(pts);
  PolygonWithHoles2 shape(toCgal(rings[0], planar.S, false));
  for (size_t r = 1; r < rings.size(); ++r) shape.add_hole(toCgal(rings[r], planar.S, true));

  // The skeleton's time grows as the cube of the corners: a large polygon's is built on a
  // worker that the deadline abandons (skeleton_roof.h).
  const auto insides = runAbandonable(deadline, pts.size() <= size_t(kInlineSkeletonCorners), [shape, distance] {
    return CGAL::create_interior_skeleton_and_offset_polygons_with_holes_2(distance, shape);
  });
  std::vector<std::vector<Vec2>> insideOutlines;
  for (const auto& piece : insides) {
    std::vector<std::vector<Vec2>> holes;
    for (auto h = piece->holes_begin(); h != piece->holes_end(); ++h) holes.push_back(toPoints(*h));
    Part part{planar, {}, false, 0};
    if (!store(toPoints(piece->outer_boundary()), holes, planar.S, arena, part.geom, error)) return false;
    inside.push_back(part);
    insideOutlines.push_back(toPoints(piece->outer_boundary()));
  }
  if (!wantBorder) return true;
  // The border: the outline with every inside piece cut out; around a courtyard, also the
  // band between each inside piece's hole and the original holes within it. An original
  // hole no inside piece surrounds (the band around it vanished) is a hole of the outline's
  // band.
  std::vector<Polygon2> originalHoles;
  for (size_t r = 1; r < rings.size(); ++r) originalHoles.push_back(toCgal(rings[r], planar.S, true));
  std::vector<bool> placed(originalHoles.size(), false);
  auto addBorder = [&](const Polygon2& outline, const std::vector<std::vector<Vec2>>& holes) {
    Part part{planar, {}, false, 0};
    if (!store(toPoints(outline), holes, planar.S, arena, part.geom, error)) return false;
    border.push_back(part);
    return true;
  };
  std::vector<std::vector<Vec2>> outlineHoles;
  for (const auto& piece : insides) {
    Polygon2 outline = piece->outer_boundary();
    outline.reverse_orientation();
    outlineHoles.push_back(toPoints(outline));
    for (auto h = piece->holes_begin(); h != piece->holes_end(); ++h) {
      Polygon2 court = *h;
      if (!court.is_counterclockwise_oriented()) court.reverse_orientation();
      std::vector<std::vector<Vec2>> within;
      for (size_t k = 0; k < originalHoles.size(); ++k)
        if (!placed[k] && court.bounded_side(originalHoles[k].vertex(0)) == CGAL::ON_BOUNDED_SIDE)
          within.push_back(toPoints(originalHoles[k])), placed[k] = true;
      if (!addBorder(court, within)) return false;
    }
  }
  for (size_t k = 0; k < originalHoles.size(); ++k)
    if (!placed[k]) outlineHoles.push_back(toPoints(originalHoles[k]));
  if (!addBorder(toCgal(rings[0], planar.S, false), outlineHoles)) return false;
  return true;
}

}  // namespace fgsg::rt::cga
