// The offset surface of Chan & Hui 2013 §6.3: a convex surface keeps the full step
// everywhere; where the full step makes the offset intersect itself or the mesh (a
// crowded torus hole, a sphere under a sheet, a narrow valley) the steps shrink there
// until nothing intersects, which an independent brute-force check confirms; the result
// does not depend on the thread count; bad input is refused.
#include "runtime/evolve/offset_surface.h"
#include "runtime/surface/load_surface.h"
#include "runtime/surface/procedural.h"

#include <catch2/catch.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

using namespace fgsg::rt;
using namespace fgsg::rt::evolve;
using surface::SurfaceMesh;

namespace {

// ---- the brute-force check: every pair, exact constructions --------------------------
// A second implementation of the rule of offset_surface.h: the intersection of two
// triangles is *constructed* exactly (Epeck) and is contact, not intersection, only when it
// is exactly what they share by identity (the shared corner, or the shared edge).

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using EP = EK::Point_3;

struct Tri {
  std::array<Vec3, 3> p;
  std::array<int, 3> id;
  Vec3 lo, hi;
};

Tri makeTri(const std::array<Vec3, 3>& p, const std::array<int, 3>& id) {
  Tri t{p, id, p[0], p[0]};
  for (const Vec3& q : p) t.lo = t.lo.cwiseMin(q), t.hi = t.hi.cwiseMax(q);
  return t;
}

EP ep(const Vec3& v) { return EP(v.x(), v.y(), v.z()); }

bool bruteIntersect(const Tri& a, const Tri& b) {
  for (int k = 0; k < 3; ++k)
    if (a.lo[k] > b.hi[k] || b.lo[k] > a.hi[k]) return false;
  std::vector<EP> shared;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a.id[i] == b.id[j]) shared.push_back(ep(a.p[i]));
  if (shared.size() == 3) return false;
  const EK::Triangle_3 ta(ep(a.p[0]), ep(a.p[1]), ep(a.p[2])), tb(ep(b.p[0]), ep(b.p[1]), ep(b.p[2]));
  const auto r = CGAL::intersection(ta, tb);
  if (!r) return false;
  if (shared.empty()) return true;
  if (const EP* p = boost::get<EP>(&*r)) return shared.size() != 1 || *p != shared[0];
  if (const EK::Segment_3* s = boost::get<EK::Segment_3>(&*r))
    return shared.size() != 2 || !((s->source() == shared[0] && s->target() == shared[1]) ||
                                   (s->source() == shared[1] && s->target() == shared[0]));
  return true;  // a triangle or a polygon: an overlap
}

// The offset faces `faces` (all when empty) against every offset and mesh face, as
// offsetContacts() reports them.
std::vector<OffsetContact> bruteContacts(const SurfaceMesh& m, const std::vector<double>& h,
                                         std::vector<int> faces = {}) {
  const int F = int(m.faces.size()), V = int(m.vertices.size());
  std::vector<Tri> offset, mesh;
  for (const auto& f : m.faces) {
    std::array<Vec3, 3> p, q;
    std::array<int, 3> id;
    for (int k = 0; k < 3; ++k) {
      const int v = f[k];
      q[k] = m.vertices[v];
      p[k] = q[k] + h[v] * m.vertexNormals[v];
      id[k] = h[v] > 0 ? V + v : v;
    }
    offset.push_back(makeTri(p, id));
    mesh.push_back(makeTri(q, f));
  }
  const bool all = faces.empty();
  if (all) faces.resize(F), std::iota(faces.begin(), faces.end(), 0);
  std::vector<OffsetContact> out;
  for (int a : faces) {
    for (int b = 0; b < F; ++b)
      if (b != a && (b > a || !all) && bruteIntersect(offset[a], offset[b]))
        out.push_back({std::min(a, b), std::max(a, b), false});
    for (int g = 0; g < F; ++g)
      if (bruteIntersect(offset[a], mesh[g])) out.push_back({a, g, true});
  }
  std::sort(out.begin(), out.end(), [](const OffsetContact& x, const OffsetContact& y) {
    return std::tie(x.offsetFace, x.faceIsMesh, x.face) < std::tie(y.offsetFace, y.faceIsMesh, y.face);
  });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double diagonal(const SurfaceMesh& m) { return (m.boundsMax - m.boundsMin).norm(); }

// Two meshes as one (two components).
SurfaceMesh join(const SurfaceMesh& a, const SurfaceMesh& b) {
  SurfaceMesh m;
  m.vertices = a.vertices;
  m.faces = a.faces;
  const int n = int(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto f : b.faces) m.faces.push_back({f[0] + n, f[1] + n, f[2] + n});
  m.buildTopology();
  return m;
}

SurfaceMesh translated(SurfaceMesh m, const Vec3& by) {
  for (Vec3& v : m.vertices) v += by;
  m.buildTopology();
  return m;
}

void requireSane(const OffsetSurface& s, const SurfaceMesh& m) {
  REQUIRE(s.height.size() == m.vertices.size());
  REQUIRE(s.vertices.size() == m.vertices.size());
  for (size_t v = 0; v < m.vertices.size(); ++v) {
    REQUIRE(s.height[v] >= 0);
    REQUIRE(s.height[v] <= s.fullStep);
    REQUIRE((s.vertices[v] - (m.vertices[v] + s.height[v] * m.vertexNormals[v])).norm() == 0);
  }
}

}  // namespace

TEST_CASE("a convex surface keeps the full step everywhere, in one round", "[offset]") {
  const SurfaceMesh m = surface::sphere(1.0, 3);
  const OffsetSurface s = offsetSurface(m);
  CHECK(s.fullStep == Approx(0.1 * diagonal(m)).epsilon(1e-12));
  CHECK(s.fullStep == Approx(0.1 * std::sqrt(12.0)).epsilon(1e-3));  // bbox of the unit sphere
  CHECK(s.rounds == 1);
  CHECK(s.initialContacts == 0);
  CHECK(s.revertedVertices == 0);
  CHECK(s.zeroedVertices == 0);
  CHECK(s.intersectionFree);
  requireSane(s, m);
  for (double h : s.height) REQUIRE(h == s.fullStep);
  // The offset of a sphere along its (angle-weighted, so nearly radial) normals is nearly
  // a sphere of radius 1 + step.
  for (const Vec3& v : s.vertices) REQUIRE(v.norm() == Approx(1 + s.fullStep).epsilon(1e-5));  // normals near radial
  CHECK(bruteContacts(m, s.height).empty());

  OffsetOptions o;
  o.fraction = 0.25;
  CHECK(offsetSurface(m, o).fullStep == Approx(0.25 * diagonal(m)).epsilon(1e-12));
}

TEST_CASE("contact is not intersection: a flat sheet, lifted evenly or pinched to the mesh", "[offset]") {
  const SurfaceMesh m = surface::plane(2, 2, 8);
  std::vector<double> h(m.vertices.size(), 0.3);
  CHECK(offsetContacts(m, h).empty());  // coplanar neighbours, touching along edges and corners
  for (size_t v = 0; v < h.size(); v += 3) h[v] = 0;  // some corners back on the mesh
  CHECK(offsetContacts(m, h).empty());
  CHECK(bruteContacts(m, h).empty());
  std::fill(h.begin(), h.end(), 0.0);  // the offset is the mesh itself
  CHECK(offsetContacts(m, h).empty());
  const OffsetSurface s = offsetSurface(m);
  CHECK(s.rounds == 1);
  CHECK(s.revertedVertices == 0);
}

TEST_CASE("neighbours across an edge intersect only when they fold onto each other", "[offset]") {
  // Two triangles sharing the edge u v in the plane z = 0; with the normals set by hand,
  // the offset lifts u, v, a straight up to z = 1 and moves b to (0.5, -0.25, 1): over the
  // edge, onto the other triangle's side, in the same plane.
  SurfaceMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.5, 0}, {0.5, -1, 0}};  // u v b a
  m.faces = {{0, 1, 2}, {1, 0, 3}};
  m.buildTopology();
  std::vector<double> h(4, 1.0);
  CHECK(offsetContacts(m, h).empty());  // flat: touching along the edge only
  m.vertexNormals = {{0, 0, 1}, {0, 0, 1}, {0, -0.6, 0.8}, {0, 0, 1}};
  h[2] = 1.25;
  REQUIRE(m.vertices[2] + h[2] * m.vertexNormals[2] == Vec3(0.5, -0.25, 1));
  CHECK(offsetContacts(m, h) == std::vector<OffsetContact>{{0, 1, false}});
  CHECK(bruteContacts(m, h) == std::vector<OffsetContact>{{0, 1, false}});
  h[2] = 0.5;  // b' = (0.5, 0.2, 0.4): on its own side, and out of the plane
  CHECK(offsetContacts(m, h).empty());
  CHECK(bruteContacts(m, h).empty());
}

TEST_CASE("a crowded torus hole: the full step intersects, the result does not", "[offset]") {
  // Hole radius R - r = 0.1, full step 0.1 x diagonal = 0.57: the inner side's offsets
  // cross each other around the axis.
  const SurfaceMesh m = surface::torus(1.0, 0.9, 20);
  REQUIRE(m.faces.size() < 2000);
  const OffsetSurface s = offsetSurface(m);
  const std::vector<double> full(m.vertices.size(), s.fullStep);

  // The grid search finds exactly what the brute force finds, at the full step.
  const std::vector<OffsetContact> atFull = offsetContacts(m, full);
  CHECK(atFull.size() > 100);
  CHECK(atFull == bruteContacts(m, full));
  CHECK(s.initialContacts == atFull.size());

  CHECK(s.intersectionFree);
  CHECK(s.rounds > 1);
  CHECK(s.rounds <= 30);
  CHECK(s.zeroedVertices == 0);
  CHECK(s.revertedVertices > 0);
  requireSane(s, m);
  CHECK(offsetContacts(m, s.height).empty());
  CHECK(bruteContacts(m, s.height).empty());

  // Outer equator (distance R + r from the axis): convex, the full step. Inner equator
  // (R - r): cut below the half gap to the axis.
  for (size_t v = 0; v < m.vertices.size(); ++v) {
    const Vec3& x = m.vertices[v];
    const double rho = std::hypot(x.x(), x.y());
    if (std::abs(x.z()) > 1e-9) continue;
    if (rho > 1.8) CHECK(s.height[v] == s.fullStep);
    if (rho < 0.2) CHECK(s.height[v] < 0.1);
  }
}

TEST_CASE("an offset must not pierce the mesh: a sphere just under a sheet", "[offset]") {
  // The sphere's top is 0.05 under the sheet; the sheet's offset goes up, away from it, so
  // offset against offset never meets: only the offset-against-mesh test sees the sphere's
  // offset crossing the sheet.
  const double gap = 0.05;
  const SurfaceMesh m = join(translated(surface::sphere(1.0, 2), Vec3(0, 0, -1 - gap)), surface::plane(4, 4, 16));
  const int sphereVertices = int(surface::sphere(1.0, 2).vertices.size());
  const OffsetSurface s = offsetSurface(m);
  CHECK(s.fullStep > 5 * gap);
  CHECK(s.initialContacts > 0);
  CHECK(s.intersectionFree);
  requireSane(s, m);
  for (size_t v = sphereVertices; v < m.vertices.size(); ++v) REQUIRE(s.height[v] == s.fullStep);  // the sheet
  double top = -10;
  for (int v = 0; v < sphereVertices; ++v) top = std::max(top, s.vertices[v].z());
  CHECK(top < 0);  // the sphere's offset stays under the sheet
  CHECK(bruteContacts(m, s.height).empty());
}

TEST_CASE("a narrow valley: the offset of one wall crosses the other", "[offset]") {
  // Two triangles sharing the edge u v, 6 degrees apart, opening upwards. Their offsets
  // share that edge and lie in different planes, so they only touch there; but each one's
  // far corner, lifted by the full step, passes the other wall.
  const double angle = 6 * 3.14159265358979 / 180;
  SurfaceMesh m;
  m.vertices = {{0, -1, 0}, {0, 1, 0}, {std::sin(angle / 2), 0, std::cos(angle / 2)},
                {-std::sin(angle / 2), 0, std::cos(angle / 2)}};
  m.faces = {{1, 0, 2}, {0, 1, 3}};  // normals point into the valley
  m.buildTopology();
  REQUIRE(m.faceNormals[0].x() < 0);
  const std::vector<double> full(4, 0.1 * diagonal(m));
  const std::vector<OffsetContact> atFull = offsetContacts(m, full);
  CHECK(atFull == std::vector<OffsetContact>{{0, 1, true}, {1, 0, true}});
  CHECK(atFull == bruteContacts(m, full));
  const OffsetSurface s = offsetSurface(m);
  CHECK(s.intersectionFree);
  CHECK(s.height[2] < s.fullStep);
  CHECK(s.height[3] < s.fullStep);
  // The far corners end within the valley's width there.
  CHECK(s.height[2] < 2 * std::sin(angle / 2));
  CHECK(bruteContacts(m, s.height).empty());
}

TEST_CASE("after maxRounds, vertices still in the way go back onto the mesh", "[offset]") {
  const SurfaceMesh m = surface::torus(1.0, 0.9, 20);
  OffsetOptions o;
  o.maxRounds = 2;  // one halving, then straight to 0
  const OffsetSurface s = offsetSurface(m, o);
  CHECK(s.intersectionFree);
  CHECK(s.zeroedVertices > 0);
  CHECK(s.rounds >= 3);
  requireSane(s, m);
  for (double h : s.height) REQUIRE((h == 0 || h == s.fullStep || h == s.fullStep / 2));
  CHECK(bruteContacts(m, s.height).empty());
}

TEST_CASE("a mesh that intersects itself cannot have a free offset, and the rounds end", "[offset]") {
  // Two unit spheres one apart, as one mesh: their faces cross along a circle.
  const SurfaceMesh m = join(surface::sphere(1.0, 2), translated(surface::sphere(1.0, 2), Vec3(1, 0, 0)));
  OffsetOptions o;
  o.maxRounds = 5;
  const OffsetSurface s = offsetSurface(m, o);
  CHECK_FALSE(s.intersectionFree);
  CHECK(s.zeroedVertices > 0);
  requireSane(s, m);
  // What is left is the mesh's own crossing: offset faces lying on their mesh faces.
  const std::vector<OffsetContact> left = offsetContacts(m, s.height);
  REQUIRE_FALSE(left.empty());
  for (const OffsetContact& c : left) {
    for (int v : m.faces[c.offsetFace]) REQUIRE(s.height[v] == 0);
    if (!c.faceIsMesh)
      for (int v : m.faces[c.face]) REQUIRE(s.height[v] == 0);
  }
}

TEST_CASE("heightAt interpolates the vertex heights", "[offset]") {
  const SurfaceMesh m = surface::torus(1.0, 0.9, 12);
  const OffsetSurface s = offsetSurface(m);
  REQUIRE(s.revertedVertices > 0);
  bool sawDifferent = false;
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const auto& c = m.faces[f];
    for (int k = 0; k < 3; ++k) {
      surface::SurfacePoint p{int(f), Vec3::Zero()};
      p.bary[k] = 1;
      REQUIRE(heightAt(s, m, p) == s.height[c[k]]);
    }
    const double mean = (s.height[c[0]] + s.height[c[1]] + s.height[c[2]]) / 3;
    REQUIRE(heightAt(s, m, surface::SurfacePoint{int(f)}) == Approx(mean).epsilon(1e-12));
    sawDifferent = sawDifferent || s.height[c[0]] != s.height[c[1]];
  }
  CHECK(sawDifferent);
  CHECK_THROWS_AS(heightAt(s, m, surface::SurfacePoint{}), std::invalid_argument);
  CHECK_THROWS_AS(heightAt(s, m, surface::SurfacePoint{int(m.faces.size())}), std::invalid_argument);
}

TEST_CASE("the bunny's offset is free of intersections", "[offset]") {
  SurfaceMesh m;
  std::string error;
  REQUIRE(surface::loadSurface(std::string(FGSG_SOURCE_DIR) + "/tests/data/meshes/bunny00.off", m, error));
  const OffsetSurface s = offsetSurface(m);
  INFO("rounds " << s.rounds << ", reverted " << s.revertedVertices << " of " << m.vertices.size());
  CHECK(s.initialContacts > 0);
  CHECK(s.intersectionFree);
  CHECK(s.rounds <= 30);
  requireSane(s, m);
  CHECK(offsetContacts(m, s.height).empty());
  // Brute force on a sample: every 300th face plus the faces around the most reverted
  // vertices (where the search had most to do).
  std::vector<int> sample;
  for (int f = 0; f < int(m.faces.size()); f += 300) sample.push_back(f);
  for (int f = 0; f < int(m.faces.size()) && sample.size() < 500; ++f) {
    const auto& c = m.faces[f];
    if (std::min({s.height[c[0]], s.height[c[1]], s.height[c[2]]}) < s.fullStep / 8) sample.push_back(f);
  }
  CHECK(bruteContacts(m, s.height, sample).empty());
}

TEST_CASE("the offset does not depend on the run or the thread count", "[offset]") {
  const SurfaceMesh m = surface::torus(1.0, 0.9, 48);
  const OffsetSurface a = offsetSurface(m);
  const OffsetSurface b = offsetSurface(m);
  OffsetSurface c;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    c = offsetSurface(m);
  }
  REQUIRE(a.revertedVertices > 0);
  CHECK(a.vertices == b.vertices);
  CHECK(a.vertices == c.vertices);
  CHECK(a.height == c.height);
  CHECK(a.rounds == c.rounds);
  CHECK(a.initialContacts == c.initialContacts);
}

TEST_CASE("bad input is refused", "[offset]") {
  const SurfaceMesh sphere = surface::sphere(1.0, 1);
  auto fails = [&](OffsetOptions o, const std::string& what) {
    try {
      offsetSurface(sphere, o);
      FAIL("no exception for " << what);
    } catch (const std::invalid_argument& e) {
      CHECK_THAT(e.what(), Catch::Contains(what));
    }
  };
  OffsetOptions o;
  o.fraction = 0, fails(o, "fraction must be finite and > 0");
  o.fraction = -1, fails(o, "fraction");
  o.fraction = std::nan(""), fails(o, "fraction");
  o.fraction = std::numeric_limits<double>::infinity(), fails(o, "fraction");
  o = {}, o.shrink = 1, fails(o, "shrink must lie strictly between 0 and 1");
  o.shrink = 0, fails(o, "shrink");
  o.shrink = std::nan(""), fails(o, "shrink");
  o = {}, o.maxRounds = 0, fails(o, "maxRounds");

  CHECK_THROWS_WITH(offsetSurface(SurfaceMesh{}), Catch::Contains("no faces"));
  SurfaceMesh bare;
  bare.vertices = sphere.vertices, bare.faces = sphere.faces;
  CHECK_THROWS_WITH(offsetSurface(bare), Catch::Contains("buildTopology"));
  CHECK_THROWS_AS(offsetContacts(sphere, {1.0}), std::invalid_argument);
  CHECK_THROWS_AS(offsetContacts(sphere, std::vector<double>(sphere.vertices.size(), -1.0)), std::invalid_argument);

  Deadline past = Deadline::after(1e-9);
  while (!past.passed()) {}
  o = {}, o.deadline = &past;
  CHECK_THROWS_AS(offsetSurface(sphere, o), TimeLimitReached);
}

// Figures for the report: `test_evolve "[.offset-perf]"`.
TEST_CASE("offset surface timings", "[.offset-perf]") {
  auto time = [](const char* name, const SurfaceMesh& m) {
    const auto t0 = std::chrono::steady_clock::now();
    const OffsetSurface s = offsetSurface(m);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto t1 = std::chrono::steady_clock::now();
    offsetContacts(m, s.height);
    const double one = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    std::printf("%-22s %7zu faces: %2d rounds, %6zu contacts at the full step, %6zu of %6zu vertices "
                "reverted (%zu to 0), %s, %.3f s total, %.3f s per search\n",
                name, m.faces.size(), s.rounds, s.initialContacts, s.revertedVertices, m.vertices.size(),
                s.zeroedVertices, s.intersectionFree ? "free" : "NOT FREE", total, one);
  };
  SurfaceMesh bunny;
  std::string error;
  REQUIRE(surface::loadSurface(std::string(FGSG_SOURCE_DIR) + "/tests/data/meshes/bunny00.off", bunny, error));
  time("bunny", bunny);
  time("torus(1, 0.9, 212)", surface::torus(1.0, 0.9, 212));
  time("torus(1, 0.4, 150)", surface::torus(1.0, 0.4, 150));
  time("sphere(1, 6)", surface::sphere(1.0, 6));
}
