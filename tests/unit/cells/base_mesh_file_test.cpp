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
