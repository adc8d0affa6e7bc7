// CityEngine's occlusion queries on real geometry and the scope distance of
// minimumDistance (runtime/cga/occlusion_geometry.h), on boxes, an L-shaped prism and
// flat pieces whose answers follow from their coordinates (each case says how).
#include "runtime/cga/occlusion_geometry.h"
#include "runtime/cga/polygon_clip.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

Scope box(double x0, double y0, double z0, double x1, double y1, double z1) {
  Scope s;
  s.P = Vec3(x0, y0, z0);
  s.S = Vec3(x1 - x0, y1 - y0, z1 - z0);
  return s;
}

TriangleSoup boxSoup(double x0, double y0, double z0, double x1, double y1, double z1) {
  return shapeTriangles(box(x0, y0, z0, x1, y1, z1), GeomRef{}, GeometryArena{});
}

bool inside(const TriangleSoup& q, const TriangleSoup& o) { return contact(Contact::Inside, q, o); }
bool overlaps(const TriangleSoup& q, const TriangleSoup& o) { return contact(Contact::Overlaps, q, o); }
bool touches(const TriangleSoup& q, const TriangleSoup& o) { return contact(Contact::Touches, q, o); }

// A prism over a polygon in the XY plane from z0 to z1, as triangles (caps ear-clipped).
TriangleSoup prism(const std::vector<Vec3>& ring, double z0, double z1) {
  std::vector<std::array<Vec3, 3>> tris;
  std::vector<uint32_t> cap;
  earClip(ring, cap);
  for (size_t k = 0; k + 2 < cap.size(); k += 3) {
    auto at = [&](uint32_t i, double z) { return Vec3(ring[i].x(), ring[i].y(), z); };
    tris.push_back({at(cap[k], z1), at(cap[k + 1], z1), at(cap[k + 2], z1)});
    tris.push_back({at(cap[k], z0), at(cap[k + 2], z0), at(cap[k + 1], z0)});
  }
  for (size_t i = 0; i < ring.size(); ++i) {
    const Vec3 &a = ring[i], &b = ring[(i + 1) % ring.size()];
    const Vec3 a0(a.x(), a.y(), z0), b0(b.x(), b.y(), z0), a1(a.x(), a.y(), z1), b1(b.x(), b.y(), z1);
    tris.push_back({a0, b0, b1});
    tris.push_back({a0, b1, a1});
  }
  return fromTriangles(std::move(tris));
}

}  // namespace

TEST_CASE("occlusion: a box and the boxes around it", "[cga][occlusion]") {
  const TriangleSoup tower = boxSoup(0, 0, 0, 10, 10, 10);
  REQUIRE(tower.closed);
  // [2,6]^3 lies 2 m inside every face of [0,10]^3.
  const TriangleSoup guest = boxSoup(2, 2, 2, 6, 6, 6);
  CHECK(inside(guest, tower));
  CHECK(overlaps(guest, tower));
  CHECK(touches(guest, tower));
  CHECK_FALSE(inside(tower, guest));
  CHECK(overlaps(tower, guest));  // "or vice versa": the guest lies in the tower
  // [10,20] x [0,4] x [0,10] shares the plane x = 10 with the tower over 4 x 10 m.
  const TriangleSoup annex = boxSoup(10, 0, 0, 20, 4, 10);
  CHECK_FALSE(inside(annex, tower));
  CHECK_FALSE(overlaps(annex, tower));
  CHECK(touches(annex, tower));
  // [8,12] x [0,2] x [0,2] reaches 2 m into the tower, 2 m out.
  const TriangleSoup straddle = boxSoup(8, 0, 0, 12, 2, 2);
  CHECK_FALSE(inside(straddle, tower));
  CHECK(overlaps(straddle, tower));
  CHECK(touches(straddle, tower));
  // The same box as the tower: inside it (on its surface everywhere) and overlapping.
  const TriangleSoup twin = boxSoup(0, 0, 0, 10, 10, 10);
  CHECK(inside(twin, tower));
  CHECK(overlaps(twin, tower));
  // [5,15] x [0,10]^2 half in: its face x = 5 lies inside the tower, no corner does.
  CHECK(overlaps(boxSoup(5, 0, 0, 15, 10, 10), tower));
}

TEST_CASE("occlusion: contact tolerance", "[cga][occlusion]") {
  const TriangleSoup a = boxSoup(0, 0, 0, 10, 10, 10);
  // A gap of 0.05 mm is within the 0.1 mm tolerance, one of 1 mm is not.
  CHECK(touches(boxSoup(10.00005, 0, 0, 12, 10, 10), a));
  CHECK_FALSE(touches(boxSoup(10.001, 0, 0, 12, 10, 10), a));
  // An overlap of 0.05 mm is only a touch, one of 1 mm an overlap.
  CHECK_FALSE(overlaps(boxSoup(9.99995, 0, 0, 12, 10, 10), a));
  CHECK(overlaps(boxSoup(9.999, 0, 0, 12, 10, 10), a));
  // Boxes meeting along an edge only (x = 10, y = 10) touch.
  CHECK(touches(boxSoup(10, 10, 0, 12, 12, 10), a));
}

TEST_CASE("occlusion: two bars crossing like a plus", "[cga][occlusion]") {
  // [0,3] x [1,2] x [0,1] and [1,2] x [0,3] x [0,1]: no corner of either is inside the
  // other, their common part is the unit cube [1,2] x [1,2] x [0,1].
  const TriangleSoup a = boxSoup(0, 1, 0, 3, 2, 1), b = boxSoup(1, 0, 0, 2, 3, 1);
  CHECK(overlaps(a, b));
  CHECK(overlaps(b, a));
  CHECK_FALSE(inside(a, b));
}

TEST_CASE("occlusion: a concave occluder", "[cga][occlusion]") {
  // An L: the 10 x 10 square without [2,10] x [2,10], 1 m thick.
  const TriangleSoup l = prism({{0, 0, 0}, {10, 0, 0}, {10, 2, 0}, {2, 2, 0}, {2, 10, 0}, {0, 10, 0}}, 0, 1);
  REQUIRE(l.closed);
  // A flat triangle at z = 0.5 with corners in the arms, (1,9) (1,1) (9,1): its long side
  // crosses the notch (at (5,5), 3 m past the arms' inner edges).
  const TriangleSoup sail = fromTriangles({{Vec3(1, 9, 0.5), Vec3(1, 1, 0.5), Vec3(9, 1, 0.5)}});
  CHECK_FALSE(sail.closed);
  CHECK_FALSE(inside(sail, l));
  CHECK(overlaps(sail, l));
  // A bar from the arm's end across the notch, corners (1,9)..(9,9.5): its corners at
  // x = 9 are outside; [0.5,1.5] x [3,4] x [0.2,0.8] lies in the arm.
  CHECK_FALSE(inside(boxSoup(1, 9, 0.2, 9, 9.5, 0.8), l));
  CHECK(inside(boxSoup(0.5, 3, 0.2, 1.5, 4, 0.8), l));
  // A box in the notch, 1 m from both arms: nothing.
  CHECK_FALSE(touches(boxSoup(3, 3, 0, 9, 9, 1), l));
}

TEST_CASE("occlusion: flat pieces and open occluders", "[cga][occlusion]") {
  const TriangleSoup mass = boxSoup(0, 0, 0, 10, 10, 10);
  // A facade piece on the face x = 10 (scope with no size along x): on the surface.
  const TriangleSoup onFace = boxSoup(10, 2, 2, 10, 4, 4);
  CHECK_FALSE(onFace.closed);
  CHECK(inside(onFace, mass));
  CHECK_FALSE(overlaps(onFace, mass));
  CHECK(touches(onFace, mass));
  // The same piece 3 m in (x = 7): inside and overlapping.
  CHECK(overlaps(boxSoup(7, 2, 2, 7, 4, 4), mass));
  // An occluder that is not closed (a single face) occludes nothing.
  CHECK_FALSE(touches(mass, onFace));
}

TEST_CASE("occlusion: winding number and scope distance", "[cga][occlusion]") {
  const TriangleSoup cube = boxSoup(0, 0, 0, 1, 1, 1);
  CHECK(windingNumber(Vec3(0.5, 0.5, 0.5), cube) == Approx(1.0).margin(1e-9));
  CHECK(windingNumber(Vec3(1.5, 0.5, 0.5), cube) == Approx(0.0).margin(1e-9));
  // Two flat 10 x 10 lots side by side with a 3 m gap: 3.
  CHECK(scopeDistance(box(0, 0, 0, 10, 0, 10), box(13, 0, 0, 23, 0, 8)) == Approx(3.0).margin(1e-12));
  // Unit cubes diagonally 1 m apart in x and in y: their nearest edges are sqrt(2) apart.
  CHECK(scopeDistance(box(0, 0, 0, 1, 1, 1), box(2, 2, 0, 3, 3, 1)) == Approx(std::sqrt(2.0)).margin(1e-12));
  // One inside the other, and touching: 0.
  CHECK(scopeDistance(box(0, 0, 0, 10, 10, 10), box(2, 2, 2, 3, 3, 3)) == 0);
  CHECK(scopeDistance(box(0, 0, 0, 1, 1, 1), box(1, 0, 0, 2, 1, 1)) == 0);
  // Segment and triangle primitives: a point 2 above a triangle's inside; two skew
  // segments 1 apart.
  CHECK(pointTriangleDistance(Vec3(0.2, 0.2, 2), {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) == Approx(2.0));
  CHECK(segmentDistance(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 1), Vec3(0, 1, 1)) == Approx(1.0));
}
