// The annotated base mesh read from OBJ (base_mesh_file.h): groups become feature
// boundaries and labels (feature_mesh.h applyGroupLabels); errors name the line.
#include "runtime/cells/base_mesh_file.h"
#include "runtime/cells/feature_mesh.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace fgsg::rt;
using namespace fgsg::rt::cells;

namespace {

using Labels = std::vector<std::string>;

const double kPiOver12 = std::acos(-1.0) / 12;

// The unit cube, faces ccw from outside, written with every corner form OBJ allows; the
// top face (relative indices) is group "roof", the rest "wall".
const char* const kCube = R"(# two-group cube
mtllib cube.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1 1.0
vt 0 0
vn 0 0 1
g wall
s off
f 1//1 4//1 3//1 2//1
f 1/1 2/1 6/1 5/1
f 3/1/1 4/1/1 8/1/1 7/1/1
f 4 1 5 8
f 2 3 7 6
g roof
f -4 -3 -2 -1
)";

// A flat 2 x 1 rectangle written as two separate unit quads (the shared side's vertices
// written twice), in groups "left part" and "right".
const char* const kSplitSquare = R"(
g left part
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
f 1 2 3 4
g right
v 1 0 0
v 2 0 0
v 2 1 0
v 1 1 0
f 5 6 7 8
)";

std::string errorOf(const std::string& text) {
  try {
    parseBaseMeshObj(text, "in.obj");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("base mesh OBJ: a two-group cube gives labelled faces, edges and corners", "[cells][obj]") {
  const LabelledMesh lm = parseBaseMeshObj(kCube, "cube.obj");
  CHECK(lm.mesh.vertices.size() == 8);
  CHECK(lm.mesh.faces.size() == 12);
  CHECK(lm.groups == Labels{"wall", "roof"});
  REQUIRE(lm.triangleGroup.size() == 12);
  CHECK(std::count(lm.triangleGroup.begin(), lm.triangleGroup.end(), 1) == 2);
  CHECK(lm.mesh.neighbours.size() == 12);  // topology built

  const FeatureMesh fm = buildLabelledFeatureMesh(lm);
  REQUIRE(fm.faces.size() == 6);
  REQUIRE(fm.edges.size() == 12);
  REQUIRE(fm.corners.size() == 8);
  int roofs = 0;
  for (const auto& f : fm.faces) {
    const bool top = f.normal.z() > 0.999;
    roofs += top;
    CHECK(f.labels == (top ? Labels{"roof"} : Labels{"wall"}));
  }
  CHECK(roofs == 1);
  int topEdges = 0;
  for (const auto& e : fm.edges) {
    const bool top = e.points.front().z() == 1 && e.points.back().z() == 1;
    topEdges += top;
    CHECK(e.labels == (top ? Labels{"roof", "wall"} : Labels{"wall"}));
  }
  CHECK(topEdges == 4);
  for (const auto& c : fm.corners)
    CHECK(c.labels == (lm.mesh.vertices[c.vertex].z() == 1 ? Labels{"roof", "wall"} : Labels{"wall"}));
}

TEST_CASE("base mesh OBJ: equal positions are welded, coplanar groups are separate faces", "[cells][obj]") {
  const LabelledMesh lm = parseBaseMeshObj(kSplitSquare, "square.obj");
  CHECK(lm.mesh.vertices.size() == 6);  // the two vertices written twice are one each
  CHECK(lm.mesh.faces.size() == 4);
  CHECK(lm.groups == Labels{"left part", "right"});  // the whole rest of the `g` line

  // Without the groups the flat rectangle is one face (the default is unchanged).
  const FeatureMesh plain = buildFeatureMesh(lm.mesh);
  CHECK(plain.faces.size() == 1);
  CHECK(plain.edges.size() == 4);

  // With them: two faces; the shared side is a flat convex feature edge between them,
  // which makes its two ends corners (three feature edges meet there): 6 corners, and
  // 7 edges (left, right, the top and bottom each split in two, the divider).
  const FeatureMesh fm = buildLabelledFeatureMesh(lm);
  REQUIRE(fm.faces.size() == 2);
  CHECK(fm.corners.size() == 6);
  REQUIRE(fm.edges.size() == 7);
  int dividers = 0;
  for (const auto& e : fm.edges) {
    if (e.fold == EdgeFold::Boundary) continue;
    ++dividers;
    CHECK(e.fold == EdgeFold::Convex);
    CHECK(e.dihedralDegrees == Approx(0).margin(1e-6));
    CHECK(e.shape == EdgeShape::Line);
    CHECK(e.labels == Labels{"left part", "right"});
    CHECK(e.points.front().x() == 1);
    CHECK(e.points.back().x() == 1);
  }
  CHECK(dividers == 1);
  for (const auto& f : fm.faces) {
    CHECK(f.planar());
    CHECK(f.loops == 1);
    CHECK(f.area == Approx(1));
    CHECK(f.labels == (f.triangles == std::vector<int>{0, 1} ? Labels{"left part"} : Labels{"right"}));
  }
}

TEST_CASE("base mesh OBJ: faces before any group, o and usemtl", "[cells][obj]") {
  const LabelledMesh lm = parseBaseMeshObj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\no thing\nf 1 3 4\nusemtl  red brick \nf 2 5 3\n",
      "t.obj");
  CHECK(lm.groups == Labels{"", "thing", "red brick"});
  CHECK(lm.triangleGroup == std::vector<int>{0, 1, 2});
  const FeatureMesh fm = buildLabelledFeatureMesh(lm);
  REQUIRE(fm.faces.size() == 3);
  CHECK(fm.faces[0].labels.empty());  // the unnamed group labels nothing
  CHECK(fm.faces[1].labels == Labels{"thing"});
  CHECK(fm.faces[2].labels == Labels{"red brick"});
}

TEST_CASE("base mesh OBJ: CRLF line ends, tabs, trailing comments, a leading '+'", "[cells][obj]") {
  const LabelledMesh lm =
      parseBaseMeshObj("v 0 0 0\r\nv +1 0 0\r\nv\t0 1 0\r\ng  two words \t\r\nf 1 2 3 # a comment\r\n", "t.obj");
  CHECK(lm.groups == Labels{"two words"});
  CHECK(lm.mesh.vertices[1].x() == 1);
  CHECK(lm.mesh.faces.size() == 1);
}

TEST_CASE("base mesh OBJ: errors name the file and line", "[cells][obj]") {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  CHECK(errorOf(tri + "f 1 2 4\n") == "in.obj:4: vertex index 4 is out of range (3 vertices so far)");
  CHECK(errorOf(tri + "f 1 2 -4\n") == "in.obj:4: vertex index -4 is out of range (3 vertices so far)");
  CHECK(errorOf(tri + "f 0 1 2\n") == "in.obj:4: '0' is not a face corner (i, i/t, i//n or i/t/n)");
  CHECK(errorOf(tri + "f 1 2 3/x\n") == "in.obj:4: '3/x' is not a face corner (i, i/t, i//n or i/t/n)");
  CHECK(errorOf(tri + "f 1 2 3/1/1/1\n") == "in.obj:4: '3/1/1/1' is not a face corner (i, i/t, i//n or i/t/n)");
  CHECK(errorOf(tri + "f 1 2\n") == "in.obj:4: a face needs at least three corners");
  CHECK(errorOf(tri + "\n# a line\nl 1 2\n") == "in.obj:6: unknown statement 'l'");
  CHECK(errorOf("v 0 0 0\nv 1 nan 0\n") == "in.obj:2: 'nan' is not a finite number");
  CHECK(errorOf("v 0 0 1e999\n") == "in.obj:1: '1e999' is not a finite number");
  CHECK(errorOf("v 0 0 inf\n") == "in.obj:1: 'inf' is not a finite number");
  CHECK(errorOf("v 0 0\n") == "in.obj:1: 'v' needs three coordinates");
  CHECK(errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nf 1 2 3\nf 1 2 4\n") ==
        "in.obj:6: the face uses a vertex twice (after welding equal positions)");
  CHECK(errorOf(tri + "v 2 0 0\nf 1 2 4\n").rfind("in.obj:5: the face is degenerate", 0) == 0);
  CHECK(errorOf(tri) == "in.obj: the file has no faces");
  // Three triangles on one edge: validateSurface's finding, for the whole file.
  const std::string fin = errorOf(tri + "v 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
  CHECK(fin.rfind("in.obj: not a valid base mesh: ", 0) == 0);
  CHECK(fin.find("non-manifold") != std::string::npos);
  // Opposite orientations across an edge.
  CHECK(errorOf(tri + "v 1 1 0\nf 1 2 3\nf 2 3 4\n").find("inconsistent") != std::string::npos);

  try {
    readBaseMeshObj("/nonexistent/base.obj");
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).rfind("/nonexistent/base.obj: ", 0) == 0);
  }
}

TEST_CASE("applyGroupLabels and buildFeatureMesh check the group list", "[cells][obj]") {
  const LabelledMesh lm = parseBaseMeshObj(kCube, "cube.obj");
  const std::vector<int> shortList(3, 0);
  CHECK_THROWS_AS(buildFeatureMesh(lm.mesh, {}, &shortList), std::invalid_argument);
  FeatureMesh fm = buildFeatureMesh(lm.mesh, {}, &lm.triangleGroup);
  CHECK_THROWS_AS(applyGroupLabels(fm, lm.groups, shortList), std::invalid_argument);
  CHECK_THROWS_AS(applyGroupLabels(fm, {"only one"}, lm.triangleGroup), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------
// The example base meshes of scripts/make-cells-meshes.py (its header describes them).
// Counts are by hand from the geometry.

namespace {

LabelledMesh readAsset(const char* name) {
  return readBaseMeshObj(std::string(FGSG_SOURCE_DIR "/examples/assets/") + name);
}

bool has(const Labels& labels, const std::string& l) {
  return std::find(labels.begin(), labels.end(), l) != labels.end();
}

template <class T>
int countLabelled(const std::vector<T>& items, const std::string& l) {
  return int(std::count_if(items.begin(), items.end(), [&](const T& x) { return has(x.labels, l); }));
}

int count(const FeatureMesh& fm, EdgeDirection d) {
  return int(std::count_if(fm.edges.begin(), fm.edges.end(), [&](const FeatureEdge& e) { return e.direction == d; }));
}

int countFold(const FeatureMesh& fm, EdgeFold f) {
  return int(std::count_if(fm.edges.begin(), fm.edges.end(), [&](const FeatureEdge& e) { return e.fold == f; }));
}

}  // namespace

TEST_CASE("example base mesh: brick_building.obj", "[cells][obj][assets]") {
  const LabelledMesh lm = readAsset("brick_building.obj");
  CHECK(lm.groups == Labels{"wall", "window", "door", "arch", "roof"});
  const FeatureMesh fm = buildLabelledFeatureMesh(lm);
  // Faces: 4 walls + roof; per window (3) 4 reveals + glass; the door's 2 jambs, its
  // back face (rectangle and half disk, one plane) and the intrados under the arch.
  CHECK(fm.faces.size() == 5 + 3 * 5 + 4);
  // Edges: 8 on the open boundary (the ground on either side of the door, the jambs' and
  // the door's lower edges, the two sides, the back), 4 vertical corners, 4 round the
  // roof; per window 4 at the wall, 4 at the glass and 4 between reveals; at the door 3
  // at the wall (jamb, arch, jamb), 3 at its back face and 2 where jambs meet the arch.
  CHECK(fm.edges.size() == 8 + 4 + 4 + 3 * 12 + 8);
  CHECK(countFold(fm, EdgeFold::Boundary) == 8);
  // Corners: 8 of the block, 4 where the door meets the ground, 4 at its springing line,
  // 8 per window.
  CHECK(fm.corners.size() == 8 + 4 + 4 + 3 * 8);

  CHECK(countLabelled(fm.faces, "wall") == 4);
  CHECK(countLabelled(fm.faces, "roof") == 1);
  CHECK(countLabelled(fm.faces, "window") == 15);
  CHECK(countLabelled(fm.faces, "door") == 3);
  CHECK(countLabelled(fm.faces, "arch") == 1);
  for (const auto& f : fm.faces) {
    REQUIRE(f.labels.size() == 1);
    if (f.labels[0] != "arch") CHECK(f.planar());
    if (f.labels[0] == "wall") {
      CHECK(std::abs(f.normal.z()) < 1e-12);
      CHECK(f.vAxis.z() == Approx(1));  // courses run horizontally
    }
    if (f.labels[0] == "window") CHECK(f.loops == 1);
    if (f.labels[0] == "wall" && f.normal.y() < -0.999) {
      // The front wall: the outer loop, which runs round the door because the door reaches
      // the ground, and one loop per window.
      CHECK(f.loops == 3);
      CHECK(f.area == Approx(6 * 4.5 - 2 * 1.0 * 1.35 - 1.2 * 2.025 - 12 * 0.36 * std::sin(kPiOver12) / 2));
    } else if (f.labels[0] == "wall" && f.normal.y() > 0.999) {
      CHECK(f.loops == 2);  // the back wall and its window
    } else if (f.labels[0] == "arch") {
      CHECK(f.kind == FaceKind::Cylindrical);
      CHECK_FALSE(f.outward);  // a vault, seen from below
      CHECK(f.radius == Approx(0.6).epsilon(1e-4));
      CHECK(std::abs(f.axis.y()) == Approx(1));
      CHECK(f.loops == 1);
    }
  }
  // The arch: its rims at the wall and at the door's back are circular arcs of radius
  // 0.6 over half a turn, labelled with both sides' groups.
  std::vector<Labels> arcs;
  for (const auto& e : fm.edges)
    if (e.shape == EdgeShape::Arc) {
      arcs.push_back(e.labels);
      CHECK(e.radius == Approx(0.6).margin(1e-6));
      CHECK(e.length == Approx(0.6 * 3.14159265358979).epsilon(1e-6));
      CHECK(e.direction == EdgeDirection::Curved);
      CHECK(e.vertices.size() == 13);
    }
  std::sort(arcs.begin(), arcs.end());
  CHECK(arcs == std::vector<Labels>{{"arch", "door"}, {"arch", "wall"}});
  CHECK(countLabelled(fm.edges, "arch") == 2 + 2);  // and the joints with the jambs
}

TEST_CASE("example base mesh: stepped_column.obj", "[cells][obj][assets]") {
  const LabelledMesh lm = readAsset("stepped_column.obj");
  CHECK(lm.groups == Labels{"column", "cap"});
  const FeatureMesh fm = buildLabelledFeatureMesh(lm);
  // Faces: the plinth's 4 sides, its top ring, the column's 4 sides, the cap.
  REQUIRE(fm.faces.size() == 10);
  // Edges: 4 vertical on the plinth and 4 on the column; 4 horizontal at each of the
  // ground (boundary), the plinth's top (convex), the column's foot (concave), the cap.
  CHECK(fm.edges.size() == 24);
  CHECK(count(fm, EdgeDirection::Vertical) == 8);
  CHECK(count(fm, EdgeDirection::Horizontal) == 16);
  CHECK(countFold(fm, EdgeFold::Boundary) == 4);
  CHECK(countFold(fm, EdgeFold::Concave) == 4);
  CHECK(fm.corners.size() == 16);
  CHECK(countLabelled(fm.faces, "cap") == 1);
  CHECK(countLabelled(fm.edges, "cap") == 4);
  CHECK(countLabelled(fm.corners, "cap") == 4);
  int rings = 0;
  for (const auto& f : fm.faces) {
    CHECK(f.planar());
    rings += f.loops == 2;  // the plinth's top, round the column
  }
  CHECK(rings == 1);
}

TEST_CASE("example base mesh: stone_wall.obj", "[cells][obj][assets]") {
  const LabelledMesh lm = readAsset("stone_wall.obj");
  CHECK(lm.groups == Labels{"wall", "window", "door", "arch"});
  const FeatureMesh fm = buildLabelledFeatureMesh(lm);
  // Faces: front, back, 2 ends, top, the window's 4 reveals and the doorway's 2 jambs
  // through the wall, and its arch's intrados (cylindrical).
  REQUIRE(fm.faces.size() == 12);
  // Edges: 8 on the ground (the doorway cuts front and back, and its jambs stand on
  // it), 4 vertical at the ends, 4 round the top; the window's rims on both sides (4 + 4,
  // convex) and 4 concave between its reveals; the doorway's jambs (2 + 2) and arch (an
  // arc each side), and 2 concave where the jambs meet the intrados.
  CHECK(fm.edges.size() == 36);
  CHECK(countFold(fm, EdgeFold::Concave) == 6);
  CHECK(fm.corners.size() == 24);
  CHECK(countLabelled(fm.faces, "window") == 4);
  CHECK(countLabelled(fm.edges, "window") == 12);
  CHECK(countLabelled(fm.corners, "window") == 8);
  CHECK(countLabelled(fm.faces, "door") == 2);
  CHECK(countLabelled(fm.faces, "arch") == 1);
  int pierced = 0, arcs = 0;
  for (const auto& f : fm.faces) {
    if (has(f.labels, "window")) CHECK(f.area == Approx(0.9 * 0.6));
    if (has(f.labels, "door")) CHECK(f.area == Approx(1.2 * 0.6));
    CHECK(f.kind == (has(f.labels, "arch") ? FaceKind::Cylindrical : FaceKind::Planar));
    pierced += f.loops == 2;  // front and back, round the window
  }
  for (const auto& e : fm.edges)
    if (e.shape == EdgeShape::Arc) {
      ++arcs;
      CHECK(e.radius == Approx(0.45).epsilon(1e-3));
    }
  CHECK(pierced == 2);
  CHECK(arcs == 2);
  // Genus 1 (the window) with two boundary loops (the footprint either side of the
  // doorway): V - E + F - (extra loops) = 2 - 2g - 2 = -2.
  CHECK(int(fm.corners.size()) - int(fm.edges.size()) + int(fm.faces.size()) - 2 == -2);
}
