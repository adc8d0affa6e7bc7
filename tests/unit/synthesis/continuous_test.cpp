// Continuous model synthesis (runtime/synthesis/continuous/): labels, the arrangement,
// constraints and the output surface, against exact values.
#include "runtime/io/write_mesh.h"
#include "runtime/synthesis/continuous/arrangement.h"
#include "runtime/synthesis/continuous/continuous.h"
#include "runtime/synthesis/continuous/inside_test.h"
#include "runtime/synthesis/continuous/labels.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

using namespace fgsg::rt;
using namespace fgsg::rt::synthesis::continuous;

namespace {

io::MeshFileContent polygons(std::vector<std::array<double, 3>> v, std::vector<std::vector<int>> faces) {
  io::MeshFileContent m;
  m.vertices = std::move(v);
  for (const auto& f : faces) {
    for (int i : f) m.corners.push_back(i);
    m.polygonStart.push_back(m.corners.size());
  }
  return m;
}

// An a x b x c box with outward quads.
io::MeshFileContent box(double a, double b, double c) {
  return polygons({{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}, {0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}},
                  {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}});
}

// An L-shaped prism (one reflex edge along z at x = y = 1).
io::MeshFileContent lShape() {
  return polygons({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0},
                   {0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}, {1, 2, 1}, {0, 2, 1}},
                  {{0, 5, 4, 3, 2, 1}, {6, 7, 8, 9, 10, 11}, {0, 1, 7, 6}, {1, 2, 8, 7}, {2, 3, 9, 8},
                   {3, 4, 10, 9}, {4, 5, 11, 10}, {5, 0, 6, 11}});
}

// The gable house of examples/synthesis/continuous/houses.obj (y up, 45-degree roof).
io::MeshFileContent house() {
  return polygons({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}, {0, 0, 2}, {2, 0, 2}, {2, 1, 2}, {1, 2, 2}, {0, 1, 2}},
                  {{0, 4, 3, 2, 1}, {5, 6, 7, 8, 9}, {0, 1, 6, 5}, {1, 2, 7, 6}, {0, 5, 9, 4}, {2, 3, 8, 7}, {4, 9, 8, 3}});
}

// The bridge of examples/synthesis/continuous/bridge.obj: piers x 0..1 and 3..4 on the
// ground, 2 high, and a deck y 2..3 over x 0..4 whose underside (x 1..3) looks down; 1 deep.
io::MeshFileContent bridge() {
  return polygons({{0, 0, 1}, {1, 0, 1}, {1, 2, 1}, {3, 2, 1}, {3, 0, 1}, {4, 0, 1}, {4, 3, 1}, {0, 3, 1},
                   {0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {3, 2, 0}, {3, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0}},
                  {{0, 1, 2, 3, 4, 5, 6, 7}, {15, 14, 13, 12, 11, 10, 9, 8}, {0, 8, 9, 1}, {1, 9, 10, 2}, {2, 10, 11, 3},
                   {3, 11, 12, 4}, {4, 12, 13, 5}, {5, 13, 14, 6}, {6, 14, 15, 7}, {7, 15, 8, 0}});
}

ExampleSolid solid(const io::MeshFileContent& m) {
  ExampleSolid s;
  std::string err;
  REQUIRE(makeExampleSolid(m, "example", s, err));
  return s;
}

std::string exampleError(const io::MeshFileContent& m) {
  ExampleSolid s;
  std::string err;
  CHECK_FALSE(makeExampleSolid(m, "example", s, err));
  return err;
}

double volume(const Mesh& m) {
  double v = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const float* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &m.positions[3 * m.indices[3 * t + k]];
    v += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
          p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) / 6.0;
  }
  return v;
}

// True when the mesh is a closed 2-manifold by OpenMesh: every face added, no boundary.
bool closedManifold(const Mesh& m) {
  OpenMesh::TriMesh_ArrayKernelT<> om;
  std::vector<OpenMesh::VertexHandle> vh;
  for (size_t v = 0; v < m.vertexCount(); ++v)
    vh.push_back(om.add_vertex({m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]}));
  for (size_t t = 0; t < m.triangleCount(); ++t)
    if (!om.add_face(vh[m.indices[3 * t]], vh[m.indices[3 * t + 1]], vh[m.indices[3 * t + 2]]).is_valid()) return false;
  for (auto h : om.halfedges())
    if (om.is_boundary(h)) return false;
  for (auto v : om.vertices())
    if (!om.is_manifold(v)) return false;
  return true;
}

// Connected parts of the mesh (triangles sharing vertices): per part, its bounding box.
std::vector<std::pair<std::array<float, 3>, std::array<float, 3>>> parts(const Mesh& m) {
  std::vector<uint32_t> up(m.vertexCount());
  std::iota(up.begin(), up.end(), 0);
  auto find = [&](uint32_t a) {
    while (up[a] != a) a = up[a] = up[up[a]];
    return a;
  };
  for (size_t t = 0; t < m.triangleCount(); ++t)
    for (int k = 1; k < 3; ++k) up[find(m.indices[3 * t + k])] = find(m.indices[3 * t]);
  std::map<uint32_t, std::pair<std::array<float, 3>, std::array<float, 3>>> box;
  for (uint32_t v = 0; v < m.vertexCount(); ++v) {
    auto [it, added] = box.emplace(find(v), std::make_pair(std::array<float, 3>{1e9f, 1e9f, 1e9f}, std::array<float, 3>{-1e9f, -1e9f, -1e9f}));
    for (int c = 0; c < 3; ++c) {
      it->second.first[size_t(c)] = std::min(it->second.first[size_t(c)], m.positions[3 * v + size_t(c)]);
      it->second.second[size_t(c)] = std::max(it->second.second[size_t(c)], m.positions[3 * v + size_t(c)]);
    }
  }
  std::vector<std::pair<std::array<float, 3>, std::array<float, 3>>> out;
  for (const auto& [k, b] : box) out.push_back(b);
  return out;
}

}  // namespace

TEST_CASE("continuous: a tetrahedron has the 16 labels of the thesis (4.5.3)", "[continuous]") {
  const ExampleSolid s = solid(polygons({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}));
  CHECK(s.faceDirections == 4);
  const LabelCatalog c = exampleLabels(s);
  // Empty, full, four faces, six edges, four vertices.
  CHECK(c.labels.size() == 16);
  size_t byUse[4] = {0, 0, 0, 0};
  for (const Label& l : c.labels) ++byUse[std::min(3, __builtin_popcount(l.dirs))];
  CHECK(byUse[0] == 2);
  CHECK(byUse[1] == 4);
  CHECK(byUse[2] == 6);
  CHECK(byUse[3] == 4);
  // A convex vertex: inside in exactly one of its eight octants.
  for (const Label& l : c.labels)
    if (__builtin_popcount(l.dirs) == 3) CHECK(l.in.size() == 1);
}

TEST_CASE("continuous: a box has 28 labels and a concave L-shape adds reflex ones", "[continuous]") {
  CHECK(exampleLabels(solid(box(2, 1, 1))).labels.size() == 28);
  // An L-shaped prism: one reflex edge (three octant quarters inside) and its two ends.
  const auto L = lShape();
  const LabelCatalog c = exampleLabels(solid(L));
  int reflexEdges = 0;
  for (const Label& l : c.labels)
    if (__builtin_popcount(l.dirs) == 2 && l.in.size() == 3) ++reflexEdges;
  CHECK(reflexEdges == 1);
  CHECK(c.labels.size() == 28 + 3);  // the reflex edge and the two vertices at its ends
}

TEST_CASE("continuous: the ray test agrees with the winding number, near faces, edges and corners too", "[continuous]") {
  // A grid of points over the bounding box (with many exactly on faces, edges and
  // vertices: those fall back to the sum) and points a small step off each vertex.
  for (const auto& mesh : {box(2, 1, 1), lShape(), house()}) {
    const ExampleSolid s = solid(mesh);
    const InsideTest test(s);
    int checked = 0, inside = 0;
    for (int i = -1; i <= 9; ++i)
      for (int j = -1; j <= 9; ++j)
        for (int k = -1; k <= 9; ++k) {
          const DVec3 p{i * 0.25 + 0.013, j * 0.25, k * 0.25 - 0.007};
          const bool expected = windingNumber(s, p) > 0.5;
          CHECK(test.inside(p) == expected);
          ++checked, inside += expected;
        }
    for (const DVec3& v : s.vertices)
      for (int d = 0; d < 27; ++d) {
        const double step = 1e-4;
        const DVec3 p{v[0] + step * (d % 3 - 1), v[1] + step * (d / 3 % 3 - 1), v[2] + step * (d / 9 - 1)};
        INFO("point " << p[0] << " " << p[1] << " " << p[2] << " winding " << windingNumber(s, p));
        CHECK(test.inside(p) == (windingNumber(s, p) > 0.5));
      }
    CHECK(inside > 0);
    CHECK(inside < checked);
    CHECK(test.fallbacks() < uint64_t(checked));  // most points take the ray
  }
}

TEST_CASE("continuous: a box cut into many coplanar quads has the box's 28 labels", "[continuous]") {
  // Each side of the unit cube as n x n quads (issue 42: thousands of them took seconds).
  const int n = 12;
  std::vector<std::array<double, 3>> v;
  std::map<std::array<int, 3>, int> index;
  std::vector<std::vector<int>> faces;
  auto at = [&](std::array<int, 3> p) {
    auto [it, added] = index.emplace(p, int(v.size()));
    if (added) v.push_back({p[0] / double(n), p[1] / double(n), p[2] / double(n)});
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {0, n})
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto corner = [&](int a, int b) {
            std::array<int, 3> p{};
            p[size_t(axis)] = side, p[size_t((axis + 1) % 3)] = a, p[size_t((axis + 2) % 3)] = b;
            return at(p);
          };
          std::vector<int> q{corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)};
          if (!side) std::reverse(q.begin(), q.end());
          faces.push_back(q);
        }
  CHECK(exampleLabels(solid(polygons(v, faces))).labels.size() == 28);
  LabelCatalog c;
  CHECK_FALSE(exampleLabels(solid(polygons(v, faces)), c, [] { return true; }));  // the time is up at once
}

TEST_CASE("continuous: the arrangement meets four directions exactly on the lattice", "[continuous]") {
  const std::vector<IVec3> axes{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Arrangement A;
  std::string err;
  REQUIRE(buildArrangement(axes, {1, 1, 1}, {2, 2, 2}, 1000, A, err));
  CHECK(A.vertexCount() == 27);
  CHECK(A.edgeCount() == 54);
  // With x + y = k as well: the same vertices, and 4 diagonal edges in each z plane.
  REQUIRE(buildArrangement({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}}, {1, 1, 1, 1}, {2, 2, 2}, 1000, A, err));
  CHECK(A.vertexCount() == 27);
  CHECK(A.edgeCount() == 66);
  // x + y = k and x - y = l also meet between lattice points (x = (k + l) / 2).
  REQUIRE(buildArrangement({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, -1, 0}}, {1, 1, 1, 1, 1}, {2, 2, 2}, 1000, A, err));
  size_t half = 0;
  for (size_t v = 0; v < A.vertexCount(); ++v) half += A.den[v] == 2;
  CHECK(half == 4 * 3);  // the centres of the four unit squares, in each of three z planes
  CHECK_FALSE(buildArrangement(axes, {1, 1, 1}, {20, 20, 20}, 100, A, err));
  CHECK(err.find("more than 100 vertices") != std::string::npos);
}

TEST_CASE("continuous: a box example gives a union of boxes on the grid", "[continuous]") {
  const ExampleSolid s = solid(box(2, 1, 1));
  ContinuousOptions o;
  o.size = {12, 6, 12};
  o.spacing = 0.5;
  o.seed = 4;
  const ContinuousResult r = synthesizeContinuous(s, o);
  REQUIRE(r.ok);
  REQUIRE(r.mesh.triangleCount() > 0);
  CHECK(closedManifold(r.mesh));
  // Every corner on the lattice (centres of fanned faces lie on half steps), every face
  // axis-aligned, the volume a whole number of cells.
  for (size_t t = 0; t < r.mesh.triangleCount(); ++t) {
    const float* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &r.mesh.positions[3 * r.mesh.indices[3 * t + k]];
    int flat = 0;
    for (int c = 0; c < 3; ++c) flat += p[0][c] == p[1][c] && p[1][c] == p[2][c];
    CHECK(flat == 1);
  }
  for (float c : r.mesh.positions) CHECK(std::fmod(double(c), 0.25) == 0.0);
  const double cells = volume(r.mesh) / (0.5 * 0.5 * 0.5);
  CHECK(cells == Approx(std::round(cells)).margin(1e-6));
  CHECK(cells >= 1);
}

TEST_CASE("continuous: the house example's outputs are closed and only convex like it", "[continuous]") {
  const ExampleSolid s = solid(house());
  CHECK(s.faceDirections == 5);
  ContinuousOptions o;
  o.size = {16, 8, 16};
  for (uint64_t seed : {1, 2, 3}) {
    o.seed = seed;
    const ContinuousResult r = synthesizeContinuous(s, o);
    REQUIRE(r.ok);
    CHECK(r.mesh.triangleCount() > 0);
    CHECK(closedManifold(r.mesh));
    CHECK(volume(r.mesh) > 0);
  }
}

TEST_CASE("continuous: a seed gives the same bytes, another seed another model", "[continuous]") {
  const ExampleSolid s = solid(house());
  ContinuousOptions o;
  o.size = {14, 6, 14};
  o.seed = 9;
  std::string a, b, c, err;
  REQUIRE(io::encodeMesh(synthesizeContinuous(s, o).mesh, ".obj", a, err));
  REQUIRE(io::encodeMesh(synthesizeContinuous(s, o).mesh, ".obj", b, err));
  o.seed = 10;
  REQUIRE(io::encodeMesh(synthesizeContinuous(s, o).mesh, ".obj", c, err));
  CHECK(a == b);
  CHECK(a != c);
  // Blocks (Fig. 4.23) give consistent models too.
  o.block = 4;
  const ContinuousResult r = synthesizeContinuous(s, o);
  REQUIRE(r.ok);
  CHECK(r.stats.blocks > 1);
  CHECK(closedManifold(r.mesh));
}

TEST_CASE("continuous: a fixed width holds exactly (4.6.1)", "[continuous]") {
  const ExampleSolid s = solid(box(2, 1, 1));
  ContinuousOptions o;
  o.size = {16, 6, 16};
  o.fixedWidth = {{{1, 0, 0}, 3}};
  for (uint64_t seed : {1, 5}) {
    o.seed = seed;
    const ContinuousResult r = synthesizeContinuous(s, o);
    REQUIRE(r.ok);
    const auto ps = parts(r.mesh);
    REQUIRE(!ps.empty());
    for (const auto& [lo, hi] : ps) CHECK(hi[0] - lo[0] == 3.0f);
  }
  // One spacing is the thesis's basic case (Fig. 4.25): every object exactly 1 high.
  o.fixedWidth = {{{0, 1, 0}, 1}};
  const ContinuousResult flat = synthesizeContinuous(s, o);
  REQUIRE(flat.ok);
  REQUIRE(!parts(flat.mesh).empty());
  for (const auto& [lo, hi] : parts(flat.mesh)) CHECK(hi[1] - lo[1] == 1.0f);
  o.fixedWidth = {{{1, 1, 0}, 2}};
  const ContinuousResult bad = synthesizeContinuous(s, o);
  CHECK_FALSE(bad.ok);
  CHECK(bad.error.find("which no face of the example has") != std::string::npos);
}

TEST_CASE("continuous: on the ground every solid stands on the floor", "[continuous]") {
  const ExampleSolid s = solid(house());
  ContinuousOptions o;
  o.size = {20, 8, 20};
  o.onGround = true;
  o.seed = 3;
  const ContinuousResult r = synthesizeContinuous(s, o);
  REQUIRE(r.ok);
  CHECK(closedManifold(r.mesh));
  const auto ps = parts(r.mesh);
  REQUIRE(!ps.empty());
  for (const auto& [lo, hi] : ps) CHECK(lo[1] == 0.0f);
}

TEST_CASE("continuous: figures found only on the example's ground plane are not raised", "[continuous]") {
  // A box: its bottom face, 4 bottom edges and 4 bottom corners lie on its lowest level
  // only; empty, full, 5 faces, 8 edges and 4 corners occur above it.
  const LabelCatalog b = exampleLabels(solid(box(1, 1, 1)));
  REQUIRE(b.labels.size() == 28);
  REQUIRE(b.raised.size() == 28);
  CHECK(std::count(b.raised.begin(), b.raised.end(), 0) == 9);
  // The bridge: the bottom face and the bottom edges along x recur at the soffit; the
  // piers' bottom edges along z (two kinds) and their 4 kinds of foot corners do not.
  const LabelCatalog r = exampleLabels(solid(bridge()));
  CHECK(r.labels.size() == 34);
  CHECK(std::count(r.raised.begin(), r.raised.end(), 0) == 6);
}

TEST_CASE("continuous: on the ground a bridge keeps its soffit and nothing floats", "[continuous]") {
  const ExampleSolid s = solid(bridge());
  ContinuousOptions o;
  o.size = {24, 8, 24};
  o.onGround = true;
  o.fill = 0.7;
  int withSoffit = 0;
  for (uint64_t seed : {3, 5}) {
    o.seed = seed;
    const ContinuousResult r = synthesizeContinuous(s, o);
    REQUIRE(r.ok);
    CHECK(closedManifold(r.mesh));
    const auto ps = parts(r.mesh);
    REQUIRE(!ps.empty());
    for (const auto& [lo, hi] : ps) CHECK(lo[1] == 0.0f);  // every part stands on the floor
    // A soffit: a triangle looking straight down above the floor; the lowest point of a
    // part is on the floor, so each soffit is held up by solid that reaches the floor.
    double soffitArea = 0;
    for (size_t t = 0; t < r.mesh.triangleCount(); ++t) {
      const float* p[3];
      for (int k = 0; k < 3; ++k) p[k] = &r.mesh.positions[3 * r.mesh.indices[3 * t + k]];
      const double ux = p[1][0] - p[0][0], uz = p[1][2] - p[0][2], vx = p[2][0] - p[0][0], vz = p[2][2] - p[0][2];
      const double ny = uz * vx - ux * vz;  // y of (p1 - p0) x (p2 - p0)
      if (ny < 0 && p[0][1] > 0 && p[0][1] == p[1][1] && p[1][1] == p[2][1]) soffitArea += -ny / 2;
    }
    // Whole lattice cells (spacing 1): the deck's underside spans 2 between piers or more.
    CHECK(soffitArea == Approx(std::round(soffitArea)).margin(1e-6));
    withSoffit += soffitArea >= 2;
  }
  CHECK(withSoffit == 2);
  // Without the ground (--floating) the same example puts parts in the air.
  o.onGround = false;
  o.seed = 3;
  const ContinuousResult f = synthesizeContinuous(s, o);
  REQUIRE(f.ok);
  const auto ps = parts(f.mesh);
  CHECK(std::any_of(ps.begin(), ps.end(), [](const auto& p) { return p.first[1] > 0.0f; }));
}

TEST_CASE("continuous: examples that cannot be used are refused with the place", "[continuous]") {
  // A box without its top: not closed.
  auto open = box(1, 1, 1);
  open.corners.resize(open.corners.size() - 4);
  open.polygonStart.pop_back();
  CHECK(exampleError(open).find("is not closed") != std::string::npos);
  // One face turned the wrong way.
  auto turned = box(1, 1, 1);
  std::reverse(turned.corners.begin(), turned.corners.begin() + 4);
  CHECK(exampleError(turned).find("oriented inconsistently") != std::string::npos);
  // Two boxes touching at one corner.
  auto two = box(1, 1, 1);
  const auto other = box(1, 1, 1);
  for (auto v : other.vertices) two.vertices.push_back({v[0] + 1, v[1] + 1, v[2] + 1});
  for (size_t p = 0; p < other.polygonCount(); ++p) {
    for (size_t c = other.polygonStart[p]; c < other.polygonStart[p + 1]; ++c) two.corners.push_back(other.corners[c] + 8);
    two.polygonStart.push_back(two.corners.size());
  }
  CHECK(exampleError(two).find("not a manifold at the vertex (1.000, 1.000, 1.000)") != std::string::npos);
  // A face at 72 degrees (a regular pentagon's side): no small integer direction.
  const double c72 = std::cos(72 * M_PI / 180), s72 = std::sin(72 * M_PI / 180);
  const auto skew = polygons({{0, 0, 0}, {1, 0, 0}, {c72, s72, 0}, {0, 0, 1}, {1, 0, 1}, {c72, s72, 1}},
                             {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}});
  const std::string e = exampleError(skew);
  CHECK(e.find("is not within 0.1 degrees of an integer direction") != std::string::npos);
  CHECK(e.find("example: face ") == 0);
  CHECK(exampleError(polygons({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}})).find("closed solid") != std::string::npos);
  // Options out of range.
  ContinuousOptions o;
  o.spacing = 0;
  CHECK(synthesizeContinuous(solid(box(1, 1, 1)), o).error == "the spacing must be a positive number");
}

TEST_CASE("continuous: whole faces are the example's faces, part by part", "[continuous]") {
  // Gable houses cannot touch (the example has no reflex edge): each part is one house
  // with the example's seven whole faces, however long or tall.
  ContinuousOptions o;
  o.size = {24, 8, 24};
  o.onGround = true;
  o.seed = 2;
  const ContinuousResult r = synthesizeContinuous(solid(house()), o);
  REQUIRE(r.ok);
  REQUIRE(r.stats.parts > 1);
  CHECK(r.faces.size() == 7 * r.stats.parts);
  std::vector<int> perPart(r.stats.parts, 0);
  for (uint32_t p : r.facePart) ++perPart[p];
  for (int n : perPart) CHECK(n == 7);
  CHECK(r.stats.outputPolygons == r.faces.size());
  CHECK(r.stats.arrangementFaces >= r.faces.size());
}

TEST_CASE("continuous: growing from seeds gives connected parts (4.6.2)", "[continuous]") {
  // An L-shaped example may join boxes into one solid; one seed grows one part.
  const auto L = lShape();
  ContinuousOptions o;
  o.size = {16, 16, 4};
  o.fill = 0.8;
  for (int seeds : {1, 3}) {
    o.growSeeds = seeds;
    const ContinuousResult r = synthesizeContinuous(solid(L), o);
    REQUIRE(r.ok);
    CHECK(r.stats.parts >= 1);
    CHECK(r.stats.parts <= size_t(seeds));
    CHECK(closedManifold(r.mesh));
  }
}

TEST_CASE("continuous: no solid where the mask is light (4.6.3)", "[continuous]") {
  ContinuousOptions o;
  o.size = {20, 6, 20};
  o.fill = 0.9;
  // Solid allowed only in the left half of the floor (x < 10).
  o.maskWidth = 2;
  o.maskHeight = 1;
  o.mask = {1.0f, 0.0f};
  const ContinuousResult r = synthesizeContinuous(solid(box(2, 1, 1)), o);
  REQUIRE(r.ok);
  REQUIRE(r.mesh.vertexCount() > 0);
  for (size_t v = 0; v < r.mesh.vertexCount(); ++v) CHECK(r.mesh.positions[3 * v] < 10.0f);
  o.mask = {1.0f};  // the wrong size
  CHECK(synthesizeContinuous(solid(box(2, 1, 1)), o).error == "the mask's size does not match its pixels");
}

TEST_CASE("continuous: perturbed parts move apart from the grid, not into each other (4.8)", "[continuous]") {
  ContinuousOptions o;
  o.size = {24, 8, 24};
  o.onGround = true;
  o.seed = 2;
  const ContinuousResult still = synthesizeContinuous(solid(house()), o);
  o.perturb = 0.4;
  const ContinuousResult moved = synthesizeContinuous(solid(house()), o);
  REQUIRE(moved.ok);
  REQUIRE(moved.mesh.vertexCount() == still.mesh.vertexCount());
  CHECK(closedManifold(moved.mesh));
  int off = 0;
  for (size_t i = 0; i < moved.mesh.positions.size(); ++i) {
    const float d = std::abs(moved.mesh.positions[i] - still.mesh.positions[i]);
    CHECK(d <= 0.4f + 1e-5f);
    if (i % 3 == 1) CHECK(d == 0.0f);  // never up or down
    off += d > 0;
  }
  CHECK(off > 0);
  const auto ps = parts(moved.mesh);
  for (size_t a = 0; a < ps.size(); ++a)
    for (size_t b = a + 1; b < ps.size(); ++b) {
      const bool apart = ps[a].second[0] <= ps[b].first[0] || ps[b].second[0] <= ps[a].first[0] ||
                         ps[a].second[2] <= ps[b].first[2] || ps[b].second[2] <= ps[a].first[2];
      CHECK(apart);
    }
}

TEST_CASE("continuous: a mirror makes the output its own mirror image", "[continuous]") {
  for (int axis : {0, 2}) {
    ContinuousOptions o;
    o.size = {17, 8, 13};
    o.onGround = true;
    o.mirrorAxes = {axis};
    o.seed = 5;
    const ContinuousResult r = synthesizeContinuous(solid(house()), o);
    REQUIRE(r.ok);
    REQUIRE(r.mesh.triangleCount() > 0);
    CHECK(closedManifold(r.mesh));
    std::set<std::array<float, 3>> points;
    for (size_t v = 0; v < r.mesh.vertexCount(); ++v)
      points.insert({r.mesh.positions[3 * v], r.mesh.positions[3 * v + 1], r.mesh.positions[3 * v + 2]});
    for (auto p : points) {
      p[size_t(axis)] = float(o.size[size_t(axis)]) - p[size_t(axis)];
      CHECK(points.count(p) == 1);
    }
  }
  // A shed: one slope, whose mirror image the example lacks.
  const auto shed = polygons({{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 2, 1}, {0, 1, 1}},
                             {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {1, 2, 6, 5}, {0, 4, 7, 3}});
  ContinuousOptions o;
  o.size = {8, 4, 8};
  o.mirrorAxes = {0};
  const ContinuousResult bad = synthesizeContinuous(solid(shed), o);
  CHECK_FALSE(bad.ok);
  CHECK(bad.error.find("has no mirror image among them") != std::string::npos);
  o.mirrorAxes = {2};  // across z the shed is its own image
  CHECK(synthesizeContinuous(solid(shed), o).ok);
}

TEST_CASE("continuous: a pyramid roof scales a tower's x and z together (4.6.4)", "[continuous]") {
  ExampleSolid tower;
  std::string err;
  REQUIRE(loadExampleSolid(FGSG_SOURCE_DIR "/examples/synthesis/continuous/tower.obj", tower, err));
  ContinuousOptions o;
  o.size = {24, 10, 24};
  o.onGround = true;
  for (uint64_t seed : {1, 2, 3}) {
    o.seed = seed;
    const ContinuousResult r = synthesizeContinuous(tower, o);
    REQUIRE(r.ok);
    const auto ps = parts(r.mesh);
    REQUIRE(!ps.empty());
    for (const auto& [lo, hi] : ps) {
      CHECK(hi[0] - lo[0] == hi[2] - lo[2]);  // a square footprint: a round tower fits
      CHECK(lo[1] == 0.0f);
    }
  }
}

TEST_CASE("continuous: a plane step keeps every N-th plane of a direction (4.5.8)", "[continuous]") {
  ContinuousOptions o;
  o.size = {16, 8, 16};
  o.onGround = true;
  const ContinuousResult all = synthesizeContinuous(solid(house()), o);
  o.planeStep = {{{1, 1, 0}, 2}, {{-1, 1, 0}, 2}};
  const ContinuousResult half = synthesizeContinuous(solid(house()), o);
  REQUIRE(all.ok);
  REQUIRE(half.ok);
  CHECK(half.stats.vertices < all.stats.vertices);
  CHECK(closedManifold(half.mesh));
  // Roof slopes only on every other plane: on each sloped triangle, x + y (or y - x) is even.
  for (size_t t = 0; t < half.mesh.triangleCount(); ++t) {
    const float* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &half.mesh.positions[3 * half.mesh.indices[3 * t + k]];
    const bool up = p[0][0] + p[0][1] == p[1][0] + p[1][1] && p[1][0] + p[1][1] == p[2][0] + p[2][1];
    const bool down = p[0][1] - p[0][0] == p[1][1] - p[1][0] && p[1][1] - p[1][0] == p[2][1] - p[2][0];
    if (up && !(p[0][0] == p[1][0] && p[1][0] == p[2][0])) CHECK(std::fmod(double(p[0][0] + p[0][1]), 2.0) == 0.0);
    if (down && !(p[0][0] == p[1][0] && p[1][0] == p[2][0])) CHECK(std::fmod(double(p[0][1] - p[0][0]), 2.0) == 0.0);
  }
  o.planeStep = {{{1, 2, 0}, 2}};
  const ContinuousResult bad = synthesizeContinuous(solid(house()), o);
  CHECK_FALSE(bad.ok);
  CHECK(bad.error.find("a plane step names the direction (1, 2, 0), which no face of the example has") == 0);
}
