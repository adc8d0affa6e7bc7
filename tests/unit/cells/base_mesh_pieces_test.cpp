// A base mesh from a grammar's pieces (base_mesh_pieces.h): welding, T-junctions,
// orientation, and the features and labels that result.
#include "runtime/cells/base_mesh_pieces.h"
#include "runtime/cells/feature_mesh.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

using namespace fgsg::rt;
using namespace fgsg::rt::cells;

namespace {

// The rectangle [x0, x1] x [y0, y1] in the plane z = z0, looking along +Z.
LabelledPolygon rect(const std::string& label, double x0, double y0, double x1, double y1, double z0 = 0) {
  return {label, {Vec3(x0, y0, z0), Vec3(x1, y0, z0), Vec3(x1, y1, z0), Vec3(x0, y1, z0)}};
}

// A 3 x 3 wall split the way a facade grammar splits it: a full-height column on each
// side, the middle column cut into wall | window | wall. The columns' long sides meet the
// middle pieces' corners in T-junctions.
std::vector<LabelledPolygon> wallWithWindow() {
  return {rect("wall", 0, 0, 1, 3), rect("wall", 1, 0, 2, 1), rect("window", 1, 1, 2, 2), rect("wall", 1, 2, 2, 3),
          rect("wall", 2, 0, 3, 3)};
}

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

}  // namespace

TEST_CASE("Pieces with T-junctions join into one surface whose window is a labelled face", "[cells][pieces]") {
  const LabelledMesh lm = labelledMeshFromPolygons(wallWithWindow());
  CHECK(lm.mesh.vertices.size() == 12);  // the pieces' corners, each once
  CHECK(lm.groups == std::vector<std::string>{"wall", "window"});
  for (size_t t = 0; t < lm.mesh.faces.size(); ++t) CHECK(lm.mesh.faceNormals[t].z() == Approx(1.0));
  double area = 0;
  for (double a : lm.mesh.faceAreas) area += a;
  CHECK(area == Approx(9.0));

  const FeatureMesh fm = buildLabelledFeatureMesh(lm);
  REQUIRE(fm.faces.size() == 2);  // the wall around it, and the window
  const auto window = std::find_if(fm.faces.begin(), fm.faces.end(), [](const FeatureFace& f) { return has(f.labels, "window"); });
  REQUIRE(window != fm.faces.end());
  CHECK(window->area == Approx(1.0));
  CHECK(window->labels == std::vector<std::string>{"window"});
  int windowEdges = 0;
  for (const FeatureEdge& e : fm.edges)
    if (has(e.labels, "window")) {
      ++windowEdges;
      CHECK(has(e.labels, "wall"));
    }
  CHECK(windowEdges >= 1);
  const auto wall = std::find_if(fm.faces.begin(), fm.faces.end(), [](const FeatureFace& f) { return has(f.labels, "wall"); });
  CHECK(wall->area == Approx(8.0));
  CHECK(wall->loops == 2);  // its outline and the window's hole
}

TEST_CASE("Corners a split reached by different sums weld, and pieces without an area are dropped", "[cells][pieces]") {
  std::vector<LabelledPolygon> pieces = wallWithWindow();
  pieces[1].points[2].x() += 3e-15;  // 1 + 1 computed as 0.1 * 20, say
  pieces[2].points[0].y() -= 2e-15;
  pieces.push_back(rect("wall", 0, 3, 3, 3));  // a zero-height piece
  const LabelledMesh lm = labelledMeshFromPolygons(pieces);
  CHECK(lm.mesh.vertices.size() == 12);
  CHECK(buildLabelledFeatureMesh(lm).faces.size() == 2);
}

TEST_CASE("A recess written as a box's outward faces is turned to look out of the opening", "[cells][pieces]") {
  // The window of the wall above, 0.25 deep: its box's faces (left, right, top, bottom,
  // back) as Comp writes them, each looking away from the box, that is into the wall.
  std::vector<LabelledPolygon> pieces = wallWithWindow();
  pieces.erase(pieces.begin() + 2);
  const double d = -0.25;
  pieces.push_back({"window", {Vec3(1, 1, 0), Vec3(1, 1, d), Vec3(1, 2, d), Vec3(1, 2, 0)}});  // left, normal -X
  pieces.push_back({"window", {Vec3(2, 1, 0), Vec3(2, 2, 0), Vec3(2, 2, d), Vec3(2, 1, d)}});  // right, +X
  pieces.push_back({"window", {Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(2, 1, d), Vec3(1, 1, d)}});  // sill, -Y
  pieces.push_back({"window", {Vec3(1, 2, 0), Vec3(1, 2, d), Vec3(2, 2, d), Vec3(2, 2, 0)}});  // head, +Y
  pieces.push_back({"window", {Vec3(1, 1, d), Vec3(1, 2, d), Vec3(2, 2, d), Vec3(2, 1, d)}});  // back, -Z
  const LabelledMesh lm = labelledMeshFromPolygons(pieces);
  const FeatureMesh fm = buildLabelledFeatureMesh(lm);
  REQUIRE(fm.faces.size() == 6);  // the wall and the recess's five faces
  for (const FeatureFace& f : fm.faces) {
    const Vec3 c = [&] {
      Vec3 s = Vec3::Zero();
      for (int t : f.triangles)
        for (int v : lm.mesh.faces[t]) s += lm.mesh.vertices[v];
      return Vec3(s / (3.0 * f.triangles.size()));
    }();
    if (has(f.labels, "wall")) {
      CHECK(f.normal.z() == Approx(1.0));
    } else if (c.z() < d + 1e-9) {
      CHECK(f.normal.z() == Approx(1.0));  // the glass looks out
    } else {
      // A reveal looks towards the opening's middle (1.5, 1.5).
      CHECK(f.normal.dot(Vec3(1.5, 1.5, c.z()) - c) > 0);
    }
  }
  int sillEdges = 0;  // the outer sill edge: wall below, the sill looking up
  for (const FeatureEdge& e : fm.edges)
    if (e.rightFace >= 0 && has(e.labels, "wall") && has(e.labels, "window") &&
        (fm.faces[e.leftFace].normal.y() > 0.9 || fm.faces[e.rightFace].normal.y() > 0.9)) {
      ++sillEdges;
      CHECK(e.fold == EdgeFold::Convex);
    }
  CHECK(sillEdges == 1);
}

TEST_CASE("Pieces that cannot make a surface are refused with the place", "[cells][pieces]") {
  SECTION("three pieces at one edge") {
    std::vector<LabelledPolygon> pieces{rect("a", 0, 0, 1, 1), rect("b", 1, 0, 2, 1),
                                        {"c", {Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(1, 1, 0)}}};
    CHECK_THROWS_WITH(labelledMeshFromPolygons(pieces), Catch::Contains("three or more base pieces meet at the edge") &&
                                                             Catch::Contains("(1, 0, 0)"));
  }
  SECTION("a piece written twice") {
    CHECK_THROWS_WITH(labelledMeshFromPolygons({rect("a", 0, 0, 1, 1), rect("a", 0, 0, 1, 1), rect("b", 1, 0, 2, 1)}),
                      Catch::Contains("three or more"));
  }
  SECTION("a bow tie") {
    CHECK_THROWS_WITH(
        labelledMeshFromPolygons({{"a", {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(0, 2, 0), Vec3(1, 2, 0)}}}),
        Catch::Contains("is not a simple flat polygon"));
  }
  SECTION("nothing with an area") {
    CHECK_THROWS_WITH(labelledMeshFromPolygons({rect("a", 0, 0, 1, 0)}), Catch::Contains("no pieces with an area"));
    CHECK_THROWS_WITH(labelledMeshFromPolygons({}), Catch::Contains("no pieces with an area"));
  }
}
