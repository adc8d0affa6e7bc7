// Roofs on any footprint polygon: the straight skeleton lifted into hipped and gable roofs,
// and pyramid, shed and ridge roofs, each closed by the footprint as the bottom face.
#include "runtime/cga/skeleton_roof.h"

#include "runtime/abandonable.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/create_straight_skeleton_2.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace fgsg::rt::cga {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;
using Segment2 = Kernel::Segment_2;
using CgalPolygon = CGAL::Polygon_2<Kernel>;

constexpr double kWeldTol = 1e-9;  // relative to the footprint's extent

// Plan coordinates are (x, -z): seen from above x runs right and -z up the page, so
// counter-clockwise in plan coordinates (positive area) is counter-clockwise seen from +Y,
// the orientation CGAL expects of an outer contour.
Point2 toPlan(const Vec2& xz) { return Point2(xz.x(), -xz.y()); }
Vec2 vec(const Point2& p) { return Vec2(p.x(), p.y()); }
Vec3 toSpace(const Vec2& plan, double y) { return Vec3(plan.x(), y, -plan.y()); }

double perpDot(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double signedArea(const std::vector<Point2>& pts) {
  double twice = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    twice += perpDot(vec(pts[i]), vec(pts[(i + 1) % pts.size()]));
  return 0.5 * twice;
}

// One ring of the footprint in plan coordinates with the footprint's inside on its left:
// the outer ring counter-clockwise, holes clockwise.
struct Ring {
  std::vector<Point2> pts;
  std::vector<int> edgeNumber;  // the documented index of edge pts[k] -> pts[k + 1]
};

// The rings and a flat numbering of their vertices: vertex k of ring r is base[r] + k, and
// so is the edge starting there.
struct Footprint {
  std::vector<Ring> rings;  // the outer ring first
  std::vector<int> base;
  std::vector<int> ringOf;
  int count = 0;
  double tol = 0.0;  // points closer than this are one point

  const Point2& plan(int v) const { return rings[ringOf[v]].pts[v - base[ringOf[v]]]; }
  Vec2 point(int v) const { return vec(plan(v)); }
  int next(int v) const {
    const int r = ringOf[v], n = static_cast<int>(rings[r].pts.size());
    return base[r] + (v - base[r] + 1) % n;
  }
  int prev(int v) const {
    const int r = ringOf[v], n = static_cast<int>(rings[r].pts.size());
    return base[r] + (v - base[r] + n - 1) % n;
  }
  int edgeNumber(int e) const { return rings[ringOf[e]].edgeNumber[e - base[ringOf[e]]]; }
  // Signed distance of p from edge e's line, positive on the footprint's side.
  double inside(int e, const Vec2& p) const {
    const Vec2 a = point(e), d = (point(next(e)) - a).normalized();
    return perpDot(d, p - a);
  }
};

// Merges consecutive points closer than tol and orients the ring with the footprint's
// inside on its left, numbering its edges in the order given. False: fewer than 3 points.
bool loadRing(const std::vector<Vec2>& in, bool hole, int firstEdge, double tol, Ring& ring) {
  std::vector<Vec2> pts;
  for (const Vec2& p : in)
    if (pts.empty() || (p - pts.back()).norm() > tol) pts.push_back(p);
  while (pts.size() > 1 && (pts.front() - pts.back()).norm() <= tol) pts.pop_back();
  if (pts.size() < 3) return false;
  const int n = static_cast<int>(pts.size());
  ring.pts.clear();
  ring.edgeNumber.clear();
  for (int k = 0; k < n; ++k) {
    ring.pts.push_back(toPlan(pts[k]));
    ring.edgeNumber.push_back(firstEdge + k);
  }
  if ((signedArea(ring.pts) < 0) != hole) {
    // Walking p0, p(n-1), p(n-2), ...: edge j joins input points n-j and n-j-1.
    for (int j = 0; j < n; ++j) {
      ring.pts[j] = toPlan(pts[(n - j) % n]);
      ring.edgeNumber[j] = firstEdge + (n - 1 - j);
    }
  }
  return true;
}

bool ringsMeet(const Ring& a, const Ring& b) {
  for (std::size_t i = 0; i < a.pts.size(); ++i) {
    const Segment2 s(a.pts[i], a.pts[(i + 1) % a.pts.size()]);
    for (std::size_t j = 0; j < b.pts.size(); ++j)
      if (CGAL::do_intersect(s, Segment2(b.pts[j], b.pts[(j + 1) % b.pts.size()]))) return true;
  }
  return false;
}

bool loadFootprint(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
                   Footprint& fp, std::string& error) {
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  auto extend = [&](const std::vector<Vec2>& ring) {
    for (const Vec2& p : ring) {
      if (!p.allFinite()) return false;
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    return true;
  };
  bool finite = extend(outer);
  for (const auto& h : holes) finite = extend(h) && finite;
  if (!finite) {
    error = "Roof: the footprint has a non-finite coordinate";
    return false;
  }
  const double extent = outer.empty() ? 0.0 : (hi - lo).maxCoeff();
  fp.tol = kWeldTol * extent;

  fp.rings.assign(1 + holes.size(), Ring());
  for (std::size_t r = 0; r < fp.rings.size(); ++r) {
    const bool hole = r > 0;
    const std::string name = hole ? "hole " + std::to_string(r - 1) : "the footprint";
    if (!(extent > 0.0) || !loadRing(hole ? holes[r - 1] : outer, hole, fp.count, fp.tol, fp.rings[r])) {
      error = "Roof: " + name + " needs at least 3 distinct points";
      return false;
    }
    const Ring& ring = fp.rings[r];
    if (!CGAL::is_simple_2(ring.pts.begin(), ring.pts.end(), Kernel())) {
      error = "Roof: " + name + " intersects itself";
      return false;
    }
    if (std::abs(signedArea(ring.pts)) <= fp.tol * extent) {
      error = "Roof: " + name + " has no area";
      return false;
    }
    fp.base.push_back(fp.count);
    fp.ringOf.insert(fp.ringOf.end(), ring.pts.size(), static_cast<int>(r));
    fp.count += static_cast<int>(ring.pts.size());
  }

  auto inside = [&](const Ring& ring, const Point2& p) {
    return CGAL::bounded_side_2(ring.pts.begin(), ring.pts.end(), p, Kernel());
  };
  for (std::size_t r = 1; r < fp.rings.size(); ++r) {
    const std::string name = "Roof: hole " + std::to_string(r - 1);
    if (ringsMeet(fp.rings[0], fp.rings[r]) ||
        inside(fp.rings[0], fp.rings[r].pts[0]) != CGAL::ON_BOUNDED_SIDE) {
      error = name + " is not strictly inside the footprint";
      return false;
    }
    for (std::size_t q = 1; q < r; ++q) {
      if (ringsMeet(fp.rings[q], fp.rings[r]) ||
          inside(fp.rings[q], fp.rings[r].pts[0]) != CGAL::ON_UNBOUNDED_SIDE ||
          inside(fp.rings[r], fp.rings[q].pts[0]) != CGAL::ON_UNBOUNDED_SIDE) {
        error = name + " overlaps hole " + std::to_string(q - 1);
        return false;
      }
    }
  }
  return true;
}

// Whether the direction from v towards t leaves v into the region on the left of the
// boundary prev -> v -> next.
bool entersInside(const Point2& prev, const Point2& v, const Point2& next, const Point2& t) {
  if (CGAL::orientation(prev, v, next) != CGAL::RIGHT_TURN)  // convex or straight
    return CGAL::orientation(v, next, t) == CGAL::LEFT_TURN &&
           CGAL::orientation(v, t, prev) == CGAL::LEFT_TURN;
  // Reflex: inside unless within the (convex) outside wedge from prev around to next.
  return !(CGAL::orientation(v, prev, t) != CGAL::RIGHT_TURN &&
           CGAL::orientation(v, t, next) != CGAL::RIGHT_TURN);
}

// The footprint as one polygon of flat vertex indices, counter-clockwise seen from above:
// each hole is joined to the outer boundary by a zero-width bridge, the shortest segment
// from one of its vertices to a vertex already on the boundary that runs inside the
// footprint and meets no other edge. Holes go rightmost first, so one always has a bridge.
bool bridgeHoles(const Footprint& fp, std::vector<int>& merged) {
  merged.clear();
  for (int v = 0; v < static_cast<int>(fp.rings[0].pts.size()); ++v) merged.push_back(v);
  std::vector<int> holes;
  for (int r = 1; r < static_cast<int>(fp.rings.size()); ++r) holes.push_back(r);
  auto maxX = [&](int r) {
    double m = -std::numeric_limits<double>::infinity();
    for (const Point2& p : fp.rings[r].pts) m = std::max(m, p.x());
    return m;
  };
  std::stable_sort(holes.begin(), holes.end(), [&](int a, int b) { return maxX(a) > maxX(b); });

  auto crossesBoundary = [&](const Point2& p, const Point2& q) {
    const Segment2 s(p, q);
    auto blocks = [&](const Point2& a, const Point2& b) {
      return a != p && a != q && b != p && b != q && CGAL::do_intersect(s, Segment2(a, b));
    };
    for (std::size_t i = 0; i < merged.size(); ++i)
      if (blocks(fp.plan(merged[i]), fp.plan(merged[(i + 1) % merged.size()]))) return true;
    for (int r : holes)
      for (int v = fp.base[r]; v < fp.base[r] + static_cast<int>(fp.rings[r].pts.size()); ++v)
        if (blocks(fp.plan(v), fp.plan(fp.next(v)))) return true;
    return false;
  };

  while (!holes.empty()) {
    bool joined = false;
    for (std::size_t h = 0; h < holes.size() && !joined; ++h) {
      const int r = holes[h];
      double best = std::numeric_limits<double>::infinity();
      int bestHole = -1;
      std::size_t bestAt = 0;
      for (int v = fp.base[r]; v < fp.base[r] + static_cast<int>(fp.rings[r].pts.size()); ++v) {
        for (std::size_t m = 0; m < merged.size(); ++m) {
          const Point2 p = fp.plan(v), q = fp.plan(merged[m]);
          const double length = (vec(p) - vec(q)).squaredNorm();
          if (length >= best) continue;
          const Point2 mPrev = fp.plan(merged[(m + merged.size() - 1) % merged.size()]);
          const Point2 mNext = fp.plan(merged[(m + 1) % merged.size()]);
          if (!entersInside(mPrev, q, mNext, p) || !entersInside(fp.plan(fp.prev(v)), p, fp.plan(fp.next(v)), q) ||
              crossesBoundary(p, q))
            continue;
          best = length;
          bestHole = v;
          bestAt = m;
        }
      }
      if (bestHole < 0) continue;
      // merged[bestAt], then around the hole from bestHole back to it, then merged[bestAt] again.
      std::vector<int> loop;
      for (int v = bestHole;;) {
        loop.push_back(v);
        v = fp.next(v);
        if (v == bestHole) break;
      }
      loop.push_back(bestHole);
      loop.push_back(merged[bestAt]);
      merged.insert(merged.begin() + static_cast<std::ptrdiff_t>(bestAt) + 1, loop.begin(), loop.end());
      holes.erase(holes.begin() + static_cast<std::ptrdiff_t>(h));
      joined = true;
    }
    if (!joined) return false;
  }
  return true;
}

// Drops points equal to their predecessor, cyclically.
void removeRepeats(std::vector<int>& face) {
  face.erase(std::unique(face.begin(), face.end()), face.end());
  while (face.size() > 1 && face.front() == face.back()) face.pop_back();
}

// A roof as shared points and index faces: points[v] for v < fp.count is footprint vertex v
// on the ground; faces[e] stands on edge e (flat numbering) and starts e, next(e).
struct RoofMesh {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
};

// For each point, the index of the first point within tol of it (itself when none is).
std::vector<int> weldPoints(const std::vector<Vec3>& pts, double tol) {
  std::vector<int> order(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return pts[a].x() < pts[b].x(); });
  std::vector<int> rep(pts.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int a = order[i];
    rep[a] = a;
    for (std::size_t j = i; j-- > 0 && pts[a].x() - pts[order[j]].x() <= tol;)
      if ((pts[a] - pts[order[j]]).norm() <= tol) {
        rep[a] = rep[order[j]];
        break;
      }
  }
  return rep;
}

// The interior straight skeleton, each node lifted to offset time * slope.
// Its time grows as the cube of the corners (a comb of 1 000 teeth: minutes), and CGAL
// cannot be interrupted: past kInlineCorners it runs on a worker that `deadline` abandons.
bool hippedRoof(const Footprint& fp, double slope, RoofMesh& mesh, std::string& error, const Deadline* deadline) {
  const std::vector<Point2>& outer = fp.rings[0].pts;
  std::vector<CgalPolygon> holes;
  for (std::size_t r = 1; r < fp.rings.size(); ++r)
    holes.emplace_back(fp.rings[r].pts.begin(), fp.rings[r].pts.end());
  decltype(CGAL::create_interior_straight_skeleton_2(outer.begin(), outer.end())) skeleton;
  try {
    skeleton = runAbandonable(deadline, fp.count <= kInlineSkeletonCorners, [outer, holes] {
      return CGAL::create_interior_straight_skeleton_2(outer.begin(), outer.end(), holes.begin(), holes.end(),
                                                       Kernel());
    });
  } catch (const std::exception&) {  // a CGAL precondition failing
    skeleton.reset();
  }
  const std::string failed = "Roof: CGAL could not build the straight skeleton of the footprint";
  if (!skeleton) {
    error = failed;
    return false;
  }

  std::map<std::pair<double, double>, int> contourVertex;
  mesh.points.clear();
  for (int v = 0; v < fp.count; ++v) {
    contourVertex[{fp.point(v).x(), fp.point(v).y()}] = v;
    mesh.points.push_back(toSpace(fp.point(v), 0.0));
  }
  // CGAL may split a simultaneous event into several nodes joined by zero-length edges:
  // welding makes them one point.
  std::unordered_map<int, int> pointOf;  // CGAL vertex id -> mesh point
  std::vector<int> nodeIds;
  std::vector<Vec3> nodes;
  for (auto v = skeleton->vertices_begin(); v != skeleton->vertices_end(); ++v) {
    if (v->is_contour()) {
      const auto found = contourVertex.find({v->point().x(), v->point().y()});
      if (found == contourVertex.end()) {
        error = failed;
        return false;
      }
      pointOf[v->id()] = found->second;
    } else {
      nodeIds.push_back(v->id());
      nodes.push_back(toSpace(vec(v->point()), v->time() * slope));
    }
  }
  const std::vector<int> rep = weldPoints(nodes, fp.tol);
  std::vector<int> welded(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (rep[i] == static_cast<int>(i)) {
      welded[i] = static_cast<int>(mesh.points.size());
      mesh.points.push_back(nodes[i]);
    }
  }
  for (std::size_t i = 0; i < nodes.size(); ++i) pointOf[nodeIds[i]] = welded[rep[i]];

  // Each skeleton face's halfedge is its contour edge, running with the ring.
  mesh.faces.assign(fp.count, {});
  for (auto f = skeleton->faces_begin(); f != skeleton->faces_end(); ++f) {
    const auto contour = f->halfedge();
    const int e = pointOf.at(contour->opposite()->vertex()->id());
    if (pointOf.at(contour->vertex()->id()) != fp.next(e) || !mesh.faces[e].empty()) {
      error = failed;
      return false;
    }
    std::vector<int>& face = mesh.faces[e];
    face.push_back(e);
    for (auto h = contour; h != contour->prev(); h = h->next()) face.push_back(pointOf.at(h->vertex()->id()));
    removeRepeats(face);
  }
  for (const auto& face : mesh.faces)
    if (face.size() < 3) {
      error = failed;
      return false;
    }
  return true;
}

// Where gable face e's apex goes: along the ridge (the line where the roof planes of the
// neighbouring edges meet, equidistant from their lines) onto edge e. False when the ridge
// does not reach the inside of the edge segment at a height (a neighbour on the same line).
bool gableTop(const Footprint& fp, int e, double slope, Vec3& top) {
  const Vec2 a = fp.point(e), b = fp.point(fp.next(e));
  const int before = fp.prev(e), after = fp.next(e);
  const double fa = fp.inside(before, a) - fp.inside(after, a);
  const double fb = fp.inside(before, b) - fp.inside(after, b);
  if (std::abs(fa - fb) <= fp.tol) return false;  // the ridge runs along the edge
  const double s = fa / (fa - fb);
  const Vec2 q = a + s * (b - a);
  const double h = fp.inside(before, q) * slope;
  if (!((q - a).norm() > fp.tol && (q - b).norm() > fp.tol && s > 0.0 && s < 1.0 && h > fp.tol))
    return false;
  top = toSpace(q, h);
  return true;
}

// Turns the ends of wings (see the header) into vertical gables. Returns, for each edge,
// its gable's top (a mesh point) or -1 where the edge keeps a sloped face.
std::vector<int> makeGables(const Footprint& fp, double slope, RoofMesh& mesh) {
  const int edges = fp.count;
  std::vector<std::vector<int>> facesAt(mesh.points.size());
  for (int e = 0; e < edges; ++e)
    for (int p : mesh.faces[e])
      if (p >= edges && std::find(facesAt[p].begin(), facesAt[p].end(), e) == facesAt[p].end())
        facesAt[p].push_back(e);
  auto apexOf = [&](int e) {
    const auto& f = mesh.faces[e];
    return f.size() == 3 && f[2] >= edges ? f[2] : -1;
  };
  auto uses = [&](int point, int e) {
    return std::find(facesAt[point].begin(), facesAt[point].end(), e) != facesAt[point].end();
  };

  std::vector<int> gable(edges, -1);  // the moved apex of each gable face
  auto addGable = [&](int e, const Vec3& top) {
    gable[e] = static_cast<int>(mesh.points.size());
    mesh.points.push_back(top);
  };
  for (int e = 0; e < edges; ++e) {
    const int apex = apexOf(e);
    if (apex < 0) continue;
    const int before = fp.prev(e), after = fp.next(e);
    Vec3 top;
    if (facesAt[apex].size() == 3 && uses(apex, before) && uses(apex, after) && apexOf(before) != apex &&
        apexOf(after) != apex) {
      if (gableTop(fp, e, slope, top)) addGable(e, top);
      continue;
    }
    // Four triangles round one apex: a quadrilateral ring (handled at its first edge).
    const int r = fp.ringOf[e];
    if (facesAt[apex].size() != 4 || fp.rings[r].pts.size() != 4 || e != fp.base[r]) continue;
    bool allTriangles = true;
    for (int k = 0; k < 4; ++k) allTriangles = allTriangles && apexOf(e + k) == apex;
    if (!allTriangles) continue;
    Vec3 tops[4];
    bool ok[4];
    for (int k = 0; k < 4; ++k) ok[k] = gableTop(fp, e + k, slope, tops[k]);
    auto ridge = [&](int k) { return tops[k + 2] - tops[k]; };
    const bool pair0 = ok[0] && ok[2], pair1 = ok[1] && ok[3];
    if (!pair0 && !pair1) continue;
    int k = pair0 ? 0 : 1;
    if (pair0 && pair1) {
      const double l0 = ridge(0).norm(), l1 = ridge(1).norm();
      if (std::abs(l0 - l1) > fp.tol)
        k = l0 > l1 ? 0 : 1;
      else  // a tie: the ridge along x
        k = std::abs(ridge(0).x()) >= std::abs(ridge(1).x()) ? 0 : 1;
    }
    addGable(e + k, tops[k]);
    addGable(e + k + 2, tops[k + 2]);
  }

  // A face meeting a gable's apex takes the gable top of the gable it borders there.
  std::map<std::pair<int, int>, int> faceOfEdge;
  for (int e = 0; e < edges; ++e) {
    const auto& f = mesh.faces[e];
    for (std::size_t i = 0; i < f.size(); ++i) faceOfEdge[{f[i], f[(i + 1) % f.size()]}] = e;
  }
  std::vector<bool> moved(mesh.points.size(), false);
  for (int e = 0; e < edges; ++e)
    if (gable[e] >= 0) moved[apexOf(e)] = true;
  auto topAcross = [&](int from, int to, int apex) {
    const auto found = faceOfEdge.find({from, to});
    if (found == faceOfEdge.end()) return -1;
    const int g = found->second;
    return gable[g] >= 0 && apexOf(g) == apex ? gable[g] : -1;
  };
  std::vector<std::vector<int>> faces(edges);
  for (int e = 0; e < edges; ++e) {
    const auto& f = mesh.faces[e];
    if (gable[e] >= 0) {
      faces[e] = {f[0], f[1], gable[e]};
      continue;
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      const int p = f[i];
      if (!moved[p]) {
        faces[e].push_back(p);
        continue;
      }
      const int before = f[(i + f.size() - 1) % f.size()], after = f[(i + 1) % f.size()];
      const int first = topAcross(p, before, p), second = topAcross(after, p, p);
      if (first >= 0) faces[e].push_back(first);
      if (second >= 0 && second != first) faces[e].push_back(second);
      if (first < 0 && second < 0) faces[e].push_back(p);
    }
    removeRepeats(faces[e]);
  }
  mesh.faces.swap(faces);
  return gable;
}

// A gable roof on a convex quadrilateral with its ridge along edge k: the planes of k and
// the edge across meet in the ridge, which ends on the walls of the two edges between.
// Returns the gable tops per edge as makeGables does; empty with `error` when it cannot.
std::vector<int> indexedGable(const Footprint& fp, int k, double slope, RoofMesh& mesh, std::string& error) {
  bool convex = fp.rings.size() == 1 && fp.count == 4;
  for (int v = 0; v < fp.count && convex; ++v)
    convex = CGAL::orientation(fp.plan(fp.prev(v)), fp.plan(v), fp.plan(fp.next(v))) == CGAL::LEFT_TURN;
  if (!convex) {
    error = "Roof: a gable roof's ridge edge needs a convex quadrilateral footprint without holes";
    return {};
  }
  const int g1 = fp.next(k), across = fp.next(g1), g3 = fp.next(across);
  Vec3 t1, t3;
  if (!gableTop(fp, g1, slope, t1) || !gableTop(fp, g3, slope, t3)) {
    error = "Roof: the ridge along edge " + std::to_string(fp.edgeNumber(k)) + " does not reach both gable walls";
    return {};
  }
  mesh.points.clear();
  for (int v = 0; v < fp.count; ++v) mesh.points.push_back(toSpace(fp.point(v), 0.0));
  const int p1 = fp.count, p3 = fp.count + 1;
  mesh.points.push_back(t1);
  mesh.points.push_back(t3);
  mesh.faces.assign(fp.count, {});
  mesh.faces[k] = {k, g1, p1, p3};
  mesh.faces[g1] = {g1, across, p1};
  mesh.faces[across] = {across, g3, p3, p1};
  mesh.faces[g3] = {g3, k, p3};
  std::vector<int> gable(fp.count, -1);
  gable[g1] = p1;
  gable[g3] = p3;
  return gable;
}

// The point p of the plan at signed distances -d1 from edge e1's line and -d2 from e2's
// (outside the footprint by d1, d2), where the two lines cross; along the outward normal
// when they are parallel (a straight corner).
Vec2 outsideBoth(const Footprint& fp, int e1, double d1, int e2, double d2) {
  const Vec2 a1 = fp.point(e1), u1 = (fp.point(fp.next(e1)) - a1).normalized();
  const Vec2 a2 = fp.point(e2), u2 = (fp.point(fp.next(e2)) - a2).normalized();
  // inside(e, p) = perpDot(u, p - a) = -d  <=>  u.x p.y - u.y p.x = perpDot(u, a) - d
  const double c1 = perpDot(u1, a1) - d1, c2 = perpDot(u2, a2) - d2, det = perpDot(u1, u2);
  if (std::abs(det) <= 1e-12) return fp.point(e2) + Vec2(u1.y(), -u1.x()) * d1;
  return Vec2((c1 * u2.x() - c2 * u1.x()) / det, (c1 * u2.y() - c2 * u1.y()) / det);
}

// CityEngine's overhangs (RoofOverhang in the header): the sloped faces' footprint corners
// and gable tops move out along the lines where the faces meet (hips, valleys, ridges),
// extended; gable walls and the bottom keep the points they had.
void addOverhangs(const Footprint& fp, double angleRad, const RoofOverhang& overhang, const std::vector<int>& gable,
                  RoofMesh& mesh) {
  const int edges = fp.count;
  const double slope = std::tan(angleRad), out = overhang.eaves * std::cos(angleRad),
               drop = overhang.eaves * std::sin(angleRad);
  auto isGable = [&](int e) { return !gable.empty() && gable[e] >= 0; };
  auto reach = [&](int e) { return isGable(e) ? overhang.gables : out; };
  std::map<int, int> moved;  // old point -> the point the sloped faces take
  for (int v = 0; v < edges; ++v) {
    const int before = fp.prev(v);
    const Vec2 p = outsideBoth(fp, before, reach(before), v, reach(v));
    const double y = isGable(before) && isGable(v) ? 0.0 : -drop;
    moved[v] = static_cast<int>(mesh.points.size());
    mesh.points.push_back(toSpace(p, y));
  }
  for (int g = 0; g < edges && overhang.gables > 0.0; ++g) {
    if (!isGable(g)) continue;
    // The ridge (where the neighbours' planes meet: equal distances from their lines)
    // meets the plane `gables` outside the gable wall.
    const int b = fp.prev(g), a = fp.next(g);
    const Vec2 pb = fp.point(b), ub = (fp.point(fp.next(b)) - pb).normalized();
    const Vec2 pa = fp.point(a), ua = (fp.point(fp.next(a)) - pa).normalized();
    const Vec2 pg = fp.point(g), ug = (fp.point(fp.next(g)) - pg).normalized();
    const Vec2 w = ub - ua;
    const double c1 = perpDot(ub, pb) - perpDot(ua, pa), c2 = perpDot(ug, pg) - overhang.gables, det = perpDot(w, ug);
    if (std::abs(det) <= 1e-12) continue;
    const Vec2 q((c1 * ug.x() - c2 * w.x()) / det, (c1 * ug.y() - c2 * w.y()) / det);
    moved[gable[g]] = static_cast<int>(mesh.points.size());
    mesh.points.push_back(toSpace(q, fp.inside(b, q) * slope));
  }
  for (int e = 0; e < edges; ++e) {
    if (isGable(e)) continue;
    for (int& p : mesh.faces[e])
      if (const auto found = moved.find(p); found != moved.end()) p = found->second;
  }
}

bool pyramidRoof(const Footprint& fp, double slope, RoofMesh& mesh, std::string& error) {
  if (fp.rings.size() > 1) {
    error = "Roof: a pyramid roof needs a footprint without holes";
    return false;
  }
  double area = 0.0;
  Vec2 moment = Vec2::Zero();
  for (int v = 0; v < fp.count; ++v) {
    const Vec2 a = fp.point(v), b = fp.point(fp.next(v));
    area += 0.5 * perpDot(a, b);
    moment += perpDot(a, b) / 6.0 * (a + b);
  }
  const Vec2 centroid = moment / area;
  double reach = std::numeric_limits<double>::infinity();
  for (int e = 0; e < fp.count; ++e) reach = std::min(reach, fp.inside(e, centroid));
  if (!(reach > fp.tol)) {
    error = "Roof: a pyramid roof needs the footprint's centroid strictly inside every edge's line";
    return false;
  }
  mesh.points.clear();
  for (int v = 0; v < fp.count; ++v) mesh.points.push_back(toSpace(fp.point(v), 0.0));
  mesh.points.push_back(toSpace(centroid, reach * slope));
  mesh.faces.clear();
  for (int e = 0; e < fp.count; ++e) mesh.faces.push_back({e, fp.next(e), fp.count});
  return true;
}

// roofRidge: one ridge along x (plan y = -z constant) over the middle of the footprint's
// extent across it, the two slopes rising from the lines through its nearest and farthest
// points. A point's height above the ground on the slope over its side of the ridge.
struct RidgeRoofPlanes {
  double lo = 0.0, hi = 0.0, mid = 0.0, slope = 0.0, tol = 0.0;
  double height(const Vec2& p) const {
    const double run = p.y() >= mid ? hi - p.y() : p.y() - lo;
    return run <= tol ? 0.0 : run * slope;
  }
  // Where the segment p-q crosses the ridge line, computed from its endpoints in a fixed
  // order so that the two faces sharing the segment get the same point.
  Vec2 crossing(Vec2 p, Vec2 q) const {
    if (q.y() < p.y()) std::swap(p, q);
    const double t = (mid - p.y()) / (q.y() - p.y());
    return Vec2(p.x() + t * (q.x() - p.x()), mid);
  }
  bool crosses(const Vec2& p, const Vec2& q) const {
    return (p.y() < mid && q.y() > mid) || (p.y() > mid && q.y() < mid);
  }
  // A footprint point within the weld tolerance of the ridge line lies on it.
  Vec2 snapped(const Vec2& p) const { return std::abs(p.y() - mid) <= tol ? Vec2(p.x(), mid) : p; }
};

// The part of the footprint polygon `ring` (plan points, bridges allowed) on one side of
// the ridge, lifted onto that side's slope (Sutherland-Hodgman: a concave footprint that
// the ridge cuts into several pieces, or a courtyard it crosses, stays one polygon, its
// pieces joined by zero-width bridges along the ridge). Every edge on the ridge line is
// cut at each point of the footprint's outline there, so the two slopes and the bridges
// meet edge to edge. Empty when that side has no area.
Polygon3 ridgeRoofSlope(const std::vector<Vec2>& ring, const RidgeRoofPlanes& planes, bool farSide) {
  auto keeps = [&](const Vec2& p) { return farSide ? p.y() >= planes.mid : p.y() <= planes.mid; };
  std::vector<Vec2> clipped, onRidge;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& p = ring[i];
    const Vec2& q = ring[(i + 1) % ring.size()];
    if (keeps(p)) clipped.push_back(p);
    if (planes.crosses(p, q)) clipped.push_back(planes.crossing(p, q));
  }
  for (const Vec2& p : clipped)
    if (p.y() == planes.mid) onRidge.push_back(p);
  std::vector<Vec2> kept;
  for (std::size_t i = 0; i < clipped.size(); ++i) {
    const Vec2& p = clipped[i];
    const Vec2& q = clipped[(i + 1) % clipped.size()];
    kept.push_back(p);
    if (p.y() != planes.mid || q.y() != planes.mid) continue;
    std::vector<Vec2> between;
    for (const Vec2& r : onRidge)
      if ((r.x() - p.x()) * (q.x() - r.x()) > 0) between.push_back(r);
    std::sort(between.begin(), between.end(), [&](const Vec2& a, const Vec2& b) {
      return (a.x() - p.x()) * (q.x() - p.x()) < (b.x() - p.x()) * (q.x() - p.x());
    });
    kept.insert(kept.end(), between.begin(), between.end());
  }
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  while (kept.size() > 1 && kept.front() == kept.back()) kept.pop_back();
  // A footprint edge lying on the ridge line leaves a needle out along it on the side it
  // does not bound (there and straight back): cut it off.
  for (std::size_t i = 0; kept.size() >= 3 && i < kept.size();) {
    const std::size_t n = kept.size(), before = (i + n - 1) % n, after = (i + 1) % n;
    if (kept[before] != kept[after]) {
      ++i;
      continue;
    }
    kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(std::max(i, after)));
    kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(std::min(i, after)));
    i = 0;
  }
  Polygon3 slope;
  for (const Vec2& p : kept) slope.push_back(toSpace(p, planes.height(p)));
  if (slope.size() < 3 || newellNormal(slope).norm() <= planes.tol * planes.tol) return {};
  return slope;
}

std::vector<int> edgesInOrder(const Footprint& fp) {
  std::vector<int> byNumber(fp.count);
  for (int e = 0; e < fp.count; ++e) byNumber[fp.edgeNumber(e)] = e;
  return byNumber;
}

double maxHeight(const std::vector<Polygon3>& faces) {
  double h = 0.0;
  for (const Polygon3& f : faces)
    for (const Vec3& p : f) h = std::max(h, p.y());
  return h;
}

}  // namespace

bool skeletonRoof(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
                  SkeletonRoofKind kind, double angleDeg, std::vector<Polygon3>& faces,
                  double& height, std::string& error, std::vector<int>* faceEdges, const Deadline* deadline,
                  const RoofOverhang& overhang) {
  if (!(angleDeg > 0.0 && angleDeg < 90.0)) {
    std::ostringstream m;
    m << "Roof: the angle " << angleDeg << " must lie strictly between 0 and 90 degrees";
    error = m.str();
    return false;
  }
  Footprint fp;
  if (!loadFootprint(outer, holes, fp, error)) return false;
  std::vector<int> bottom;
  if (!bridgeHoles(fp, bottom)) {
    error = "Roof: the holes could not be joined to the footprint's outline";
    return false;
  }
  const double slope = std::tan(angleDeg * std::numbers::pi / 180.0);
  const std::vector<int> byNumber = edgesInOrder(fp);
  faces.clear();
  std::vector<int> edgeOfFace;

  if (kind == SkeletonRoofKind::Shed) {
    // Heights from edge 0's line; points on it get exactly 0 so they are the ground points.
    const int first = byNumber[0];
    std::vector<double> h(fp.count);
    for (int v = 0; v < fp.count; ++v) {
      const double d = fp.inside(first, fp.point(v));
      if (d < -fp.tol) {
        error = "Roof: a shed roof needs the whole footprint on the inner side of edge 0";
        return false;
      }
      h[v] = d <= fp.tol ? 0.0 : d * slope;
    }
    Polygon3 top;
    for (int v : bottom) top.push_back(toSpace(fp.point(v), h[v]));
    faces.push_back(std::move(top));
    edgeOfFace.push_back(0);
    for (int number = 1; number < fp.count; ++number) {
      const int a = byNumber[number], b = fp.next(a);
      Polygon3 side = {toSpace(fp.point(a), 0.0), toSpace(fp.point(b), 0.0)};
      if (h[b] > 0.0) side.push_back(toSpace(fp.point(b), h[b]));
      if (h[a] > 0.0) side.push_back(toSpace(fp.point(a), h[a]));
      if (side.size() < 3) continue;  // an edge on edge 0's line has no side
      faces.push_back(std::move(side));
      edgeOfFace.push_back(number);
    }
  } else if (kind == SkeletonRoofKind::Ridge) {
    RidgeRoofPlanes planes;
    planes.slope = slope;
    planes.tol = fp.tol;
    planes.lo = std::numeric_limits<double>::infinity();
    planes.hi = -planes.lo;
    for (const Point2& p : fp.rings[0].pts) {
      planes.lo = std::min(planes.lo, p.y());
      planes.hi = std::max(planes.hi, p.y());
    }
    planes.mid = 0.5 * (planes.lo + planes.hi);
    std::vector<Vec2> ring;
    for (int v : bottom) ring.push_back(planes.snapped(fp.point(v)));
    for (const bool farSide : {false, true}) {
      Polygon3 slopeFace = ridgeRoofSlope(ring, planes, farSide);
      if (slopeFace.empty()) continue;
      faces.push_back(std::move(slopeFace));
      edgeOfFace.push_back(-2);
    }
    // An upright side on every edge up to the slopes, through the ridge where the edge
    // crosses it; edges along the eave lines have no height and no side.
    for (int number = 0; number < fp.count; ++number) {
      const int a = byNumber[number], b = fp.next(a);
      const Vec2 pa = planes.snapped(fp.point(a)), pb = planes.snapped(fp.point(b));
      Polygon3 side = {toSpace(pa, 0.0), toSpace(pb, 0.0)};
      if (planes.height(pb) > 0.0) side.push_back(toSpace(pb, planes.height(pb)));
      if (planes.crosses(pa, pb)) {
        const Vec2 c = planes.crossing(pa, pb);
        side.push_back(toSpace(c, planes.height(c)));
      }
      if (planes.height(pa) > 0.0) side.push_back(toSpace(pa, planes.height(pa)));
      if (side.size() < 3) continue;
      faces.push_back(std::move(side));
      edgeOfFace.push_back(number);
    }
  } else {
    RoofMesh mesh;
    std::vector<int> gables;
    if (kind == SkeletonRoofKind::Gable && overhang.ridgeEdge >= 0) {
      gables = indexedGable(fp, byNumber[overhang.ridgeEdge % fp.count], slope, mesh, error);
      if (gables.empty()) return false;
    } else {
      const bool built = kind == SkeletonRoofKind::Pyramid ? pyramidRoof(fp, slope, mesh, error)
                                                           : hippedRoof(fp, slope, mesh, error, deadline);
      if (!built) return false;
      if (kind == SkeletonRoofKind::Gable) gables = makeGables(fp, slope, mesh);
    }
    if (kind != SkeletonRoofKind::Pyramid && (overhang.eaves > 0.0 || overhang.gables > 0.0))
      addOverhangs(fp, angleDeg * std::numbers::pi / 180.0, overhang, gables, mesh);
    for (int number = 0; number < fp.count; ++number) {
      Polygon3 face;
      for (int p : mesh.faces[byNumber[number]]) face.push_back(mesh.points[p]);
      faces.push_back(std::move(face));
      edgeOfFace.push_back(number);
    }
  }

  Polygon3 ground;  // seen from below: the footprint reversed
  for (auto v = bottom.rbegin(); v != bottom.rend(); ++v) ground.push_back(toSpace(fp.point(*v), 0.0));
  faces.push_back(std::move(ground));
  edgeOfFace.push_back(-1);
  height = maxHeight(faces);
  if (faceEdges) faceEdges->swap(edgeOfFace);
  return true;
}

bool joinHoles(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
               const std::string& what, std::vector<Vec2>& joined, std::string& error) {
  Footprint fp;
  std::vector<int> merged;
  if (!loadFootprint(outer, holes, fp, error) || !bridgeHoles(fp, merged)) {
    if (error.empty()) error = "Roof: the holes could not be joined to the outline";
    error = what + error.substr(std::string("Roof: ").size());
    return false;
  }
  joined.clear();
  for (int v : merged) joined.emplace_back(fp.point(v).x(), -fp.point(v).y());  // plan (x, -z) back to (x, z)
  return true;
}

bool joinHolesInPlane(const std::vector<Vec2>& outline, const std::vector<std::vector<Vec2>>& holes,
                      const std::string& what, std::vector<Vec2>& joined, std::string& error) {
  const auto mirrored = [](const std::vector<Vec2>& pts) {
    std::vector<Vec2> out;
    out.reserve(pts.size());
    for (const Vec2& p : pts) out.emplace_back(p.x(), -p.y());
    return out;
  };
  std::vector<std::vector<Vec2>> groundHoles;
  for (const auto& h : holes) groundHoles.push_back(mirrored(h));
  std::vector<Vec2> ground;
  if (!joinHoles(mirrored(outline), groundHoles, what, ground, error)) return false;
  joined = mirrored(ground);
  return true;
}

}  // namespace fgsg::rt::cga
