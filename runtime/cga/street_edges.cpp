// street.* from a lot's street widths (street_edges.h).
#include "runtime/cga/street_edges.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::cga {

namespace {

constexpr double kStreetCos45 = 0.70710678118654752 - 1e-9;  // the diagonal counts as within 45 degrees

Vec3 streetLevel(const Vec3& v) { return Vec3(v.x(), 0.0, v.z()); }

// Whether p lies on the segment a-b (within tol of it, between its ends).
bool streetPointOnEdge(const Vec3& p, const StreetEdges::Edge& e, double tol) {
  const Vec3 d = e.b - e.a;
  const double length = d.norm();
  if (!(length > 0)) return false;
  const Vec3 u = d / length;
  const Vec3 q = p - e.a;
  const double along = q.dot(u);
  return along >= -tol && along <= length + tol && (q - along * u).norm() <= tol;
}

}  // namespace

StreetEdges streetEdgesOfLot(const std::vector<Vec3>& ring, const std::vector<double>& width, const Vec3& objectFront,
                             const std::vector<std::vector<Vec3>>& holes) {
  StreetEdges out;
  double extent = 0, widest = 0;
  const StreetEdges::Edge* main = nullptr;
  for (size_t i = 0; i < ring.size() && i < width.size(); ++i) {
    StreetEdges::Edge e;
    e.a = ring[i];
    e.b = ring[(i + 1) % ring.size()];
    const Vec3 out_ = streetLevel(e.b - e.a).cross(Vec3::UnitY());  // counter-clockwise from above: the lot on its left
    e.outward = out_.norm() > 0 ? Vec3(out_.normalized()) : Vec3::Zero();
    e.width = width[i];
    extent = std::max({extent, e.a.cwiseAbs().maxCoeff(), e.b.cwiseAbs().maxCoeff()});
    out.edges.push_back(e);
  }
  for (const std::vector<Vec3>& hole : holes)
    for (size_t i = 0; i < hole.size(); ++i) {
      StreetEdges::Edge e;
      e.a = hole[i];
      e.b = hole[(i + 1) % hole.size()];
      e.outward = Vec3::Zero();
      extent = std::max({extent, e.a.cwiseAbs().maxCoeff(), e.b.cwiseAbs().maxCoeff()});
      out.holeEdges.push_back(e);
    }
  for (const StreetEdges::Edge& e : out.edges)
    if (e.width > widest && e.outward.norm() > 0) widest = e.width, main = &e;
  const Vec3 front = main ? main->outward : streetLevel(objectFront);
  if (front.norm() > 0) out.front = front.normalized();
  out.right = Vec3::UnitY().cross(out.front);  // seen from the street, looking at the lot
  out.tol = 1e-9 * (1.0 + extent);
  return out;
}

unsigned streetSide(const StreetEdges& streets, const Vec3& direction, const Vec3* a, const Vec3* b) {
  const Vec3 level = streetLevel(direction);
  if (!(level.norm() > 1e-12)) return 0;
  const Vec3 w = level.normalized();
  bool onLotEdge = false, onStreet = false;
  if (a && b)
    for (const StreetEdges::Edge& e : streets.edges)
      if (streetPointOnEdge(*a, e, streets.tol) && streetPointOnEdge(*b, e, streets.tol)) {
        onLotEdge = true;
        onStreet = e.width > 0;
        break;
      }
  if (a && b && !onLotEdge)  // a courtyard's edge: on no street, classed by its direction below
    for (const StreetEdges::Edge& e : streets.holeEdges)
      if (streetPointOnEdge(*a, e, streets.tol) && streetPointOnEdge(*b, e, streets.tol)) {
        onLotEdge = true;
        break;
      }
  if (!onLotEdge)
    for (const StreetEdges::Edge& e : streets.edges)
      if (e.width > 0 && w.dot(e.outward) >= kStreetCos45) onStreet = true;
  if (onStreet) return kStreetFront;
  const double ahead = w.dot(streets.front), across = w.dot(streets.right);
  if (-ahead >= std::abs(across) - 1e-9) return kStreetBack;
  if (across > 1e-9) return kStreetRight;
  if (across < -1e-9) return kStreetLeft;
  return 0;
}

}  // namespace fgsg::rt::cga
