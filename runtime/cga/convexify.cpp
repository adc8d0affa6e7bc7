// CityEngine's convexify(maxLength): a concave polygon cut along diagonals into convex
// pieces, kept as one shape with one face per piece (comp(f) takes them apart). CGAL's
// partition_2 does the cutting: the optimal partition (fewest pieces, diagonals between
// corners only) up to kOptimalCorners corners, Hertel-Mehlhorn beyond (O(n^4) would be too
// slow there; it gives at most four times the fewest). With maxLength, pieces that a cut
// of that length or longer separates are joined again. A polygon with courtyards is
// triangulated (CGAL's constrained Delaunay triangulation) and the triangles joined again
// across every diagonal whose removal keeps the piece convex (Hertel-Mehlhorn: at most four
// times the fewest pieces; a square ring gives its four trapezoids).
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>
#include <CGAL/Polygon_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <list>

namespace fgsg::rt::cga {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Partition_traits_2<Kernel>;
using PlanRing = std::vector<Vec2>;

constexpr size_t kOptimalCorners = 32;

double cornerCross(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Corners on a straight line between their neighbours dropped: they are no corners to cut at.
PlanRing withoutStraightCorners(const PlanRing& ring, double eps) {
  PlanRing out;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2& prev = ring[(i + n - 1) % n];
    const Vec2& next = ring[(i + 1) % n];
    if (std::abs(cornerCross(prev, ring[i], next)) > eps * (next - prev).norm()) out.push_back(ring[i]);
  }
  return out;
}

// Where ring a runs from p to q and ring b from q to p: a's index of p (or -1).
int sharedEdge(const PlanRing& a, const PlanRing& b, size_t& bIndex) {
  for (size_t i = 0; i < a.size(); ++i) {
    const Vec2& p = a[i];
    const Vec2& q = a[(i + 1) % a.size()];
    for (size_t j = 0; j < b.size(); ++j)
      if (b[j] == q && b[(j + 1) % b.size()] == p) return bIndex = j, static_cast<int>(i);
  }
  return -1;
}

// a and b joined along their shared edge (a's corner i to i + 1, b's corner j to j + 1).
PlanRing joined(const PlanRing& a, size_t i, const PlanRing& b, size_t j) {
  PlanRing out;
  for (size_t k = 0; k < a.size(); ++k) out.push_back(a[(i + 1 + k) % a.size()]);  // a from q round to p
  for (size_t k = 2; k < b.size(); ++k) out.push_back(b[(j + k) % b.size()]);      // b past p, before q
  return out;
}

// Whether a counter-clockwise ring turns left (or goes straight) at every corner.
bool convexRing(const PlanRing& r, double eps) {
  for (size_t i = 0; i < r.size(); ++i)
    if (cornerCross(r[(i + r.size() - 1) % r.size()], r[i], r[(i + 1) % r.size()]) < -eps) return false;
  return true;
}

// The polygon `outline` (counter-clockwise) less its `holes` in convex pieces: its
// constrained Delaunay triangles inside it, joined across each diagonal whose removal
// leaves the joined piece convex.
std::vector<PlanRing> convexPiecesAroundHoles(const PlanRing& outline, const std::vector<PlanRing>& holes,
                                              double eps) {
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel>;
  using Point = Kernel::Point_2;
  Cdt cdt;
  auto constrain = [&](const PlanRing& r) {
    for (size_t i = 0; i < r.size(); ++i) {
      const Vec2& a = r[i];
      const Vec2& b = r[(i + 1) % r.size()];
      cdt.insert_constraint(Point(a.x(), a.y()), Point(b.x(), b.y()));
    }
  };
  constrain(outline);
  for (const PlanRing& h : holes) constrain(h);
  auto inside = [](const PlanRing& r, const Point& p) {
    std::vector<Point> pts;
    for (const Vec2& v : r) pts.emplace_back(v.x(), v.y());
    return CGAL::bounded_side_2(pts.begin(), pts.end(), p, Kernel()) == CGAL::ON_BOUNDED_SIDE;
  };
  std::vector<PlanRing> pieces;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const Point c = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    if (!inside(outline, c)) continue;
    bool inHole = false;
    for (const PlanRing& h : holes) inHole = inHole || inside(h, c);
    if (inHole) continue;
    PlanRing t;
    for (int k = 0; k < 3; ++k) t.emplace_back(f->vertex(k)->point().x(), f->vertex(k)->point().y());
    if (cornerCross(t[0], t[1], t[2]) < 0) std::reverse(t.begin(), t.end());
    pieces.push_back(std::move(t));
  }
  for (bool joinedSome = true; joinedSome;) {
    joinedSome = false;
    for (size_t a = 0; a < pieces.size() && !joinedSome; ++a)
      for (size_t b = a + 1; b < pieces.size() && !joinedSome; ++b) {
        size_t j = 0;
        const int i = sharedEdge(pieces[a], pieces[b], j);
        if (i < 0) continue;
        PlanRing both = joined(pieces[a], static_cast<size_t>(i), pieces[b], j);
        if (!convexRing(both, eps)) continue;
        pieces[a] = withoutStraightCorners(both, eps);
        pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(b));
        joinedSome = true;
      }
  }
  return pieces;
}

}  // namespace

bool convexify(const Scope& scope, const GeomRef& geom, GeometryArena& arena, double maxLength, Part& out,
               std::string& error) {
  FlatPolygon poly;
  if (!flatPolygon(scope, geom, arena, "convexify", poly, error, true)) return false;
  const double size = (poly.scope.S.x() + poly.scope.S.y());
  const PlanRing ring = withoutStraightCorners(poly.ring, 1e-12 * size);
  out = Part{scope, geom, false, 0};
  std::vector<PlanRing> pieces;
  if (!poly.holes.empty()) {
    std::vector<PlanRing> holes;
    for (const PlanRing& h : poly.holes) holes.push_back(withoutStraightCorners(h, 1e-12 * size));
    pieces = convexPiecesAroundHoles(ring, holes, 1e-12 * size * size);
  } else {
    if (ring.size() < 4) return true;  // a triangle is convex
    std::vector<Traits::Point_2> points;
    for (const Vec2& p : ring) points.emplace_back(p.x(), p.y());
    // GCC 12 warns inside CGAL's is_simple_2 (-Wmaybe-uninitialized on a temporary it
    // builds and sets before use): a false positive in the library's code, silenced here only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
    const bool simple = CGAL::Polygon_2<Kernel>(points.begin(), points.end()).is_simple();
#pragma GCC diagnostic pop
    if (!simple) {
      error = "convexify: the polygon crosses itself";
      return false;
    }
    std::list<Traits::Polygon_2> parts;
    if (points.size() <= kOptimalCorners)
      CGAL::optimal_convex_partition_2(points.begin(), points.end(), std::back_inserter(parts));
    else
      CGAL::approx_convex_partition_2(points.begin(), points.end(), std::back_inserter(parts));
    for (const Traits::Polygon_2& part : parts) {
      PlanRing r;
      for (auto v = part.vertices_begin(); v != part.vertices_end(); ++v) r.emplace_back(v->x(), v->y());
      pieces.push_back(std::move(r));
    }
  }
  // convexify(maxLength): a cut as long as maxLength or longer is not made.
  for (bool joinedSome = true; joinedSome && std::isfinite(maxLength);) {
    joinedSome = false;
    for (size_t a = 0; a < pieces.size() && !joinedSome; ++a)
      for (size_t b = a + 1; b < pieces.size() && !joinedSome; ++b) {
        size_t j = 0;
        const int i = sharedEdge(pieces[a], pieces[b], j);
        if (i < 0 || (pieces[a][(i + 1) % pieces[a].size()] - pieces[a][i]).norm() < maxLength) continue;
        pieces[a] = joined(pieces[a], static_cast<size_t>(i), pieces[b], j);
        pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(b));
        joinedSome = true;
      }
  }
  if (pieces.size() < 2) return true;
  // One face per piece in the shape's own scope (unit-box coordinates), each facing the
  // way the polygon faces.
  std::vector<std::vector<Vec3>> faces;
  for (const PlanRing& piece : pieces) {
    std::vector<Vec3> world, local;
    for (const Vec2& p : piece) world.push_back(poly.scope.toWorld(Vec3(p.x(), p.y(), 0.0)));
    if (newellNormal(world).dot(poly.scope.Z()) < 0) std::reverse(world.begin(), world.end());
    for (const Vec3& w : world) {
      const Vec3 metres = scope.axes.transpose() * (w - scope.P);
      local.emplace_back(scope.S.x() > 0 ? metres.x() / scope.S.x() : 0.0,
                         scope.S.y() > 0 ? metres.y() / scope.S.y() : 0.0,
                         scope.S.z() > 0 ? metres.z() / scope.S.z() : 0.0);
    }
    faces.push_back(std::move(local));
  }
  out.geom = arena.addPolyhedron(faces);
  return true;
}

}  // namespace fgsg::rt::cga
