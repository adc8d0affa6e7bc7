// CityEngine's comp selectors on edges and vertices (comp(e), comp(v)) and the world.*,
// object.*, border / inside and index selectors of every component (runtime/cga/
// components.cpp): which components each selector's mask takes, by hand.
#include "runtime/cga/cga.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

// The components of `component` that the selector `name` takes (componentSelectorMask).
std::vector<Part> compSelected(const std::vector<Part>& parts, const std::string& component, const std::string& name) {
  const uint64_t mask = componentSelectorMask(component, name);
  std::vector<Part> out;
  for (const Part& p : parts)
    if (mask == ~0u || (mask & p.faceClass)) out.push_back(p);
  return out;
}

// The edges' lengths, sorted.
std::vector<double> compLengths(const std::vector<Part>& edges) {
  std::vector<double> out;
  for (const Part& e : edges) out.push_back(e.scope.S.x());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

// extrude(3) on a 4 x 2 lot: the box 4 x 3 x 2. Its vertical edges' normals are level
// (vertical), its top edges' 45 degrees up (aslant), its bottom edges' 45 down (nutant).
TEST_CASE("cga: comp(e) selectors on a 4 x 3 x 2 box", "[cga][comp]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Scope s;
  s.S = Vec3(4, 3, 2);
  REQUIRE(components(s, GeomRef{}, "e", arena, parts, err));
  REQUIRE(parts.size() == 12);
  CHECK(compLengths(compSelected(parts, "e", "vertical")) == std::vector<double>{3, 3, 3, 3});
  CHECK(compLengths(compSelected(parts, "e", "aslant")) == std::vector<double>{2, 2, 4, 4});
  CHECK(compLengths(compSelected(parts, "e", "nutant")) == std::vector<double>{2, 2, 4, 4});
  CHECK(compSelected(parts, "e", "horizontal").empty());
  // By quadrant: a top edge's normal ties top and a wall, top wins.
  const std::vector<Part> top = compSelected(parts, "e", "top");
  REQUIRE(top.size() == 4);
  for (const Part& e : top) CHECK(e.scope.P.y() == Approx(3));
  CHECK(compSelected(parts, "e", "bottom").size() == 4);
  CHECK(compLengths(compSelected(parts, "e", "side")) ==
        std::vector<double>{2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4});  // all but horizontal
  CHECK(compSelected(parts, "e", "inside").size() == 12);
  CHECK(compSelected(parts, "e", "border").empty());
  CHECK(compSelected(parts, "e", "worldUp").size() == 4);
  CHECK(compSelected(parts, "e", "objectBottom").size() == 4);
  // The vertical edge at (4, y, 2) between the front (+z) and right (+x) walls: a tie that
  // front takes; the one at (4, y, 0) between the right and back walls: back.
  int front = 0;
  for (const Part& e : compSelected(parts, "e", "front")) front += e.scope.S.x() == 3;
  CHECK(front == 2);
  CHECK(compSelected(parts, "e", "left").empty());
}

TEST_CASE("cga: comp(v) selectors on a 4 x 3 x 2 box", "[cga][comp]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Scope s;
  s.S = Vec3(4, 3, 2);
  REQUIRE(components(s, GeomRef{}, "v", arena, parts, err));
  REQUIRE(parts.size() == 8);
  std::vector<Part> top = compSelected(parts, "v", "top");
  REQUIRE(top.size() == 4);
  std::vector<std::array<double, 3>> corners;
  for (const Part& v : top) corners.push_back({v.scope.P.x(), v.scope.P.y(), v.scope.P.z()});
  std::sort(corners.begin(), corners.end());
  const std::vector<std::array<double, 3>> want = {{0, 3, 0}, {0, 3, 2}, {4, 3, 0}, {4, 3, 2}};
  CHECK(corners == want);
  CHECK(compSelected(parts, "v", "bottom").size() == 4);
  CHECK(compSelected(parts, "v", "aslant").size() == 4);  // (+-1, 1, +-1) / sqrt 3: 35 degrees up
  CHECK(compSelected(parts, "v", "nutant").size() == 4);
  CHECK(compSelected(parts, "v", "inside").size() == 8);
  CHECK(compSelected(parts, "v", "border").empty());
}

// An open lot (one face): every edge and vertex is border, its normal up (world.up).
TEST_CASE("cga: comp(e) and comp(v) of an open 4 x 2 lot are its border", "[cga][comp]") {
  GeometryArena arena;
  Part lot;
  std::string err;
  REQUIRE(footprint(Scope{}, {{0, 0}, {4, 0}, {4, 2}, {0, 2}}, {}, arena, lot, err));
  std::vector<Part> parts;
  REQUIRE(components(lot.scope, lot.geom, "e", arena, parts, err));
  REQUIRE(parts.size() == 4);
  CHECK(compLengths(compSelected(parts, "e", "border")) == std::vector<double>{2, 2, 4, 4});
  CHECK(compSelected(parts, "e", "inside").empty());
  CHECK(compSelected(parts, "e", "worldUp").size() == 4);
  // fgsg's Footprint has its normal as its scope's z: in the scope's terms the edges face
  // front (a .cga lot, whose scope has y up, has them top and horizontal).
  CHECK(compSelected(parts, "e", "front").size() == 4);
  CHECK(compSelected(parts, "e", "vertical").size() == 4);
  REQUIRE(components(lot.scope, lot.geom, "v", arena, parts, err));
  CHECK(compSelected(parts, "v", "border").size() == 4);
  REQUIRE(components(lot.scope, lot.geom, "f", arena, parts, err));
  CHECK(compSelected(parts, "f", "border").size() == 1);
}

// world.* in the world's axes, object.* in the start shape's, whatever the scope's.
TEST_CASE("cga: comp(f) world and object selectors on a turned scope", "[cga][comp]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Scope s;
  s.S = Vec3(4, 3, 2);
  // The scope turned 90 degrees about y: its x along world -z, its z (front) along world +x.
  s.axes.col(0) = Vec3(0, 0, -1);
  s.axes.col(2) = Vec3(1, 0, 0);
  // The object's axes turned the other way: its x along world +z, its z along world -x.
  Mat3 object = Mat3::Identity();
  object.col(0) = Vec3(0, 0, 1);
  object.col(2) = Vec3(-1, 0, 0);
  REQUIRE(components(s, GeomRef{}, "f", arena, parts, err, object));
  REQUIRE(parts.size() == 6);
  auto normalOf = [&](const std::string& sel) {
    const std::vector<Part> faces = compSelected(parts, "f", sel);
    REQUIRE(faces.size() == 1);
    return Vec3(faces[0].scope.Z());
  };
  CHECK((normalOf("front") - Vec3(1, 0, 0)).norm() < 1e-12);
  CHECK((normalOf("worldEast") - Vec3(1, 0, 0)).norm() < 1e-12);
  CHECK((normalOf("worldSouth") - Vec3(0, 0, 1)).norm() < 1e-12);
  CHECK((normalOf("worldNorth") - Vec3(0, 0, -1)).norm() < 1e-12);
  CHECK((normalOf("worldWest") - Vec3(-1, 0, 0)).norm() < 1e-12);
  CHECK((normalOf("worldUp") - Vec3(0, 1, 0)).norm() < 1e-12);
  CHECK((normalOf("objectFront") - Vec3(-1, 0, 0)).norm() < 1e-12);
  CHECK((normalOf("objectRight") - Vec3(0, 0, 1)).norm() < 1e-12);
  CHECK(compSelected(parts, "f", "worldSide").size() == 4);
  CHECK(compSelected(parts, "f", "objectSide").size() == 4);
  CHECK(compSelected(parts, "f", "inside").size() == 6);  // a box is closed
  CHECK(componentSelectorMask("f", "street.front") == 0);  // fgsg's label is streetFront
  CHECK(componentSelectorMask("edges", "border") == 0);  // fgsg's own edges: roof classes only
}

// street.*: the quadrant of a component's level outward direction in the object system
// (front: the start lot's first edge). A 4 x 2 Footprint lying as a lot does, corners
// (0, 0, 0) (4, 0, 0) (4, 0, -2) (0, 0, -2), normal up; its object system is the world's
// (x along edge 0, y up, z = x x y = +z): edge 0 leans out to +z, front; edge 1 (+x)
// right; edge 2 back; edge 3 left.
TEST_CASE("cga: comp(e) and comp(v) street selectors on a 4 x 2 lot", "[cga][comp]") {
  GeometryArena arena;
  Part lot;
  std::string err;
  REQUIRE(footprint(Scope{}, {{0, 0}, {4, 0}, {4, -2}, {0, -2}}, {}, arena, lot, err));
  const Mat3 object = Mat3::Identity();
  std::vector<Part> parts;
  REQUIRE(components(lot.scope, lot.geom, "e", arena, parts, err, object));
  REQUIRE(parts.size() == 4);
  const std::vector<Part> front = compSelected(parts, "e", "streetFront");
  REQUIRE(front.size() == 1);
  CHECK(front[0].scope.S.x() == Approx(4));
  CHECK(front[0].scope.P.z() == Approx(0).margin(1e-12));
  const std::vector<Part> back = compSelected(parts, "e", "streetBack");
  REQUIRE(back.size() == 1);
  CHECK(back[0].scope.P.z() == Approx(-2));
  const std::vector<Part> right = compSelected(parts, "e", "streetRight");
  REQUIRE(right.size() == 1);
  CHECK(right[0].scope.P.x() == Approx(4));
  CHECK(right[0].scope.S.x() == Approx(2));
  const std::vector<Part> left = compSelected(parts, "e", "streetLeft");
  REQUIRE(left.size() == 1);
  CHECK(left[0].scope.P.x() == Approx(0).margin(1e-12));
  CHECK(compLengths(compSelected(parts, "e", "streetSide")) == std::vector<double>{2, 2});
  // Corners lean out along both their edges: (0, 0, 0) west and south, a tie that goes to front.
  REQUIRE(components(lot.scope, lot.geom, "v", arena, parts, err, object));
  std::vector<std::array<double, 2>> corners;
  for (const Part& v : compSelected(parts, "v", "streetFront")) corners.push_back({v.scope.P.x(), v.scope.P.z()});
  std::sort(corners.begin(), corners.end());
  CHECK(corners == std::vector<std::array<double, 2>>{{0, 0}, {4, 0}});
  CHECK(compSelected(parts, "v", "streetBack").size() == 2);
  CHECK(compSelected(parts, "v", "streetSide").empty());
  // The lot's own face looks up: no street class.
  REQUIRE(components(lot.scope, lot.geom, "f", arena, parts, err, object));
  CHECK(compSelected(parts, "f", "streetFront").empty());
}

// comp(f)'s street.*: the walls by their normals in the object system (the box's scope
// turned as in the world/object test: object z, the street's front, is world -x).
TEST_CASE("cga: comp(f) street selectors follow the object system", "[cga][comp]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Scope s;
  s.S = Vec3(4, 3, 2);
  Mat3 object = Mat3::Identity();
  object.col(0) = Vec3(0, 0, 1);
  object.col(2) = Vec3(-1, 0, 0);
  REQUIRE(components(s, GeomRef{}, "f", arena, parts, err, object));
  const std::vector<Part> front = compSelected(parts, "f", "streetFront");
  REQUIRE(front.size() == 1);
  CHECK((front[0].scope.Z() - Vec3(-1, 0, 0)).norm() < 1e-12);
  const std::vector<Part> right = compSelected(parts, "f", "streetRight");
  REQUIRE(right.size() == 1);
  CHECK((right[0].scope.Z() - Vec3(0, 0, 1)).norm() < 1e-12);
  CHECK(compSelected(parts, "f", "streetSide").size() == 2);  // world +z and -z
  CHECK(compSelected(parts, "f", "streetBack").size() == 1);
  // The street bits are found only where a label asks for them (wantedClasses).
  REQUIRE(components(s, GeomRef{}, "f", arena, parts, err, object, componentSelectorMask("f", "top")));
  CHECK(compSelected(parts, "f", "streetFront").empty());
}

// `all =`: the components a merged part takes as one shape, the first one's axes fitted to
// them all. The 4 x 2 lot's edges: the first runs (0,0,0)-(4,0,0), x (1,0,0), z its normal
// (0,1,0), y = z x x = (0,0,-1): the box around all four ends is 4 x 2 at the origin.
TEST_CASE("cga: mergedComponents fits the first component's axes to them all", "[cga][comp]") {
  GeometryArena arena;
  Part lot;
  std::string err;
  REQUIRE(footprint(Scope{}, {{0, 0}, {4, 0}, {4, -2}, {0, -2}}, {}, arena, lot, err));
  std::vector<Part> parts;
  REQUIRE(components(lot.scope, lot.geom, "e", arena, parts, err));
  Part merged = mergedComponents(parts);
  CHECK((merged.scope.P - Vec3(0, 0, 0)).norm() < 1e-12);
  CHECK((merged.scope.S - Vec3(4, 2, 0)).norm() < 1e-12);
  CHECK((merged.scope.X() - Vec3(1, 0, 0)).norm() < 1e-12);
  CHECK(merged.geom.kind == GeomKind::Edge);
  // Edges 1 and 3 (x = 4 and x = 0, 2 m each): edge 1's x runs (0, 0, -1), y = z x x = (-1, 0, 0).
  merged = mergedComponents({parts[1], parts[3]});
  CHECK((merged.scope.P - Vec3(4, 0, 0)).norm() < 1e-12);
  CHECK((merged.scope.S - Vec3(2, 4, 0)).norm() < 1e-12);
  REQUIRE(components(lot.scope, lot.geom, "v", arena, parts, err));
  REQUIRE(parts.size() == 4);
  merged = mergedComponents(parts);
  CHECK((merged.scope.S - Vec3(4, 2, 0)).norm() < 1e-12);
}

// comp(f)'s `side = A`: the box 4 x 3 x 2 (x 0..4, y 0..3, z 0..2) has its side faces front
// (+z), right, back, left; merged they are one Polyhedron of 4 faces, 2 x (4 + 2) x 3 =
// 36 m2, its scope the front face's axes (x (1,0,0), y up, z (0,0,1)) around them all:
// x 0..4, y 0..3, z 0..2 at the origin. One face merged is that face as it was.
TEST_CASE("cga: mergedFaces makes one shape of the faces in the first face's axes", "[cga][comp]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Scope s;
  s.S = Vec3(4, 3, 2);
  REQUIRE(components(s, GeomRef{}, "sidefaces", arena, parts, err));
  REQUIRE(parts.size() == 4);
  REQUIRE((parts[0].scope.Z() - Vec3(0, 0, 1)).norm() < 1e-12);
  const Part merged = mergedFaces(parts, arena);
  CHECK(merged.geom.kind == GeomKind::Polyhedron);
  CHECK(merged.geom.count == 4);
  CHECK((merged.scope.X() - Vec3(1, 0, 0)).norm() < 1e-12);
  CHECK((merged.scope.Z() - Vec3(0, 0, 1)).norm() < 1e-12);
  CHECK((merged.scope.P - Vec3(0, 0, 0)).norm() < 1e-12);
  CHECK((merged.scope.S - Vec3(4, 3, 2)).norm() < 1e-12);
  // Its faces again, in the world: the four walls, 12 + 6 + 12 + 6 m2.
  std::vector<Part> again;
  REQUIRE(components(merged.scope, merged.geom, "f", arena, again, err));
  REQUIRE(again.size() == 4);
  double area = 0;
  for (const Part& f : again) area += f.scope.S.x() * f.scope.S.y();
  CHECK(area == Approx(36));
  const Part one = mergedFaces({parts[1]}, arena);
  CHECK(one.geom.kind == parts[1].geom.kind);
  CHECK((one.scope.S - parts[1].scope.S).norm() < 1e-12);
}
