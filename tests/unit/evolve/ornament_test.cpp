// One tile's ornament (Chan & Hui 2013 §2.4 Eq. 1, §5.2 on a flat tile): the blend
// surface stays in its tile, rises to the section's height, ends on the border where the
// locus does so neighbouring tiles meet exactly, turns with its allele, and does not
// intersect itself.
#include "runtime/evolve/ornament.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using namespace fgsg::rt::evolve;
using V3 = std::array<double, 3>;

namespace {

const std::string kData = std::string(FGSG_SOURCE_DIR) + "/tests/data/evolve/";

V3 sub(V3 a, V3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 cross(V3 a, V3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(V3 a, V3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(V3 a) { return std::sqrt(dot(a, a)); }

Curve polyline(std::vector<Point2> p) { return {Curve::Kind::kPolyline, std::move(p)}; }
Curve cubic(std::vector<Point2> p) { return {Curve::Kind::kCubic, std::move(p)}; }

// A semicircle-like section: 9 points on the upper unit half circle, (0, 1) among them.
Curve semicircle() {
  std::vector<Point2> p;
  for (int k = 0; k <= 8; ++k) {
    const double a = std::numbers::pi * (1 - k / 8.0);
    p.push_back({std::cos(a), std::sin(a)});
  }
  p.front() = {-1, 0}, p[4] = {0, 1}, p.back() = {1, 0};
  return polyline(p);
}

// Does segment p-q meet triangle a-b-c (touching included, within eps)? Moller-Trumbore.
bool segmentHitsTriangle(V3 p, V3 q, V3 a, V3 b, V3 c) {
  const double eps = 1e-12;
  const V3 dir = sub(q, p), e1 = sub(b, a), e2 = sub(c, a);
  const V3 h = cross(dir, e2);
  const double det = dot(e1, h);
  if (std::abs(det) < 1e-18) return false;  // parallel (coplanar overlaps are not looked for)
  const V3 s = sub(p, a);
  const double u = dot(s, h) / det;
  if (u < -eps || u > 1 + eps) return false;
  const V3 qq = cross(s, e1);
  const double v = dot(dir, qq) / det;
  if (v < -eps || u + v > 1 + eps) return false;
  const double t = dot(e2, qq) / det;
  return t >= -eps && t <= 1 + eps;
}

// Two triangles intersect when an edge of one meets the other (enough unless coplanar).
bool trianglesIntersect(const std::array<V3, 3>& x, const std::array<V3, 3>& y) {
  for (int k = 0; k < 3; ++k) {
    if (segmentHitsTriangle(x[size_t(k)], x[size_t((k + 1) % 3)], y[0], y[1], y[2])) return true;
    if (segmentHitsTriangle(y[size_t(k)], y[size_t((k + 1) % 3)], x[0], x[1], x[2])) return true;
  }
  return false;
}

// The number of pairs of triangles that share no vertex and intersect, on the grid's
// double-precision points with the mesh's triangles.
int selfIntersections(const OrnamentGrid& g, const fgsg::rt::Mesh& m) {
  const size_t n = m.triangleCount();
  std::vector<std::array<V3, 3>> tri(n);
  std::vector<std::array<V3, 2>> box(n);
  for (size_t i = 0; i < n; ++i) {
    for (size_t k = 0; k < 3; ++k) tri[i][k] = g.points[m.indices[3 * i + k]];
    for (size_t d = 0; d < 3; ++d) {
      box[i][0][d] = std::min({tri[i][0][d], tri[i][1][d], tri[i][2][d]}) - 1e-12;
      box[i][1][d] = std::max({tri[i][0][d], tri[i][1][d], tri[i][2][d]}) + 1e-12;
    }
  }
  int hits = 0;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      bool shared = false;
      for (size_t a = 0; a < 3; ++a)
        for (size_t b = 0; b < 3; ++b) shared = shared || m.indices[3 * i + a] == m.indices[3 * j + b];
      if (shared) continue;
      bool apart = false;
      for (size_t d = 0; d < 3; ++d) apart = apart || box[i][1][d] < box[j][0][d] || box[j][1][d] < box[i][0][d];
      if (!apart && trianglesIntersect(tri[i], tri[j])) ++hits;
    }
  return hits;
}

// Finite, float copy of the grid, unit normals agreeing with their faces, no zero-area
// triangle.
void checkWellFormed(const OrnamentGrid& g, const fgsg::rt::Mesh& m) {
  REQUIRE(m.vertexCount() == g.points.size());
  REQUIRE(m.triangleCount() == 2 * (g.t.size() - 1) * (g.r.size() - 1));
  REQUIRE(m.hasTexcoords());
  REQUIRE(m.normals.size() == m.positions.size());
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    for (size_t k = 0; k < 3; ++k) {
      REQUIRE(std::isfinite(g.points[v][k]));
      REQUIRE(m.positions[3 * v + k] == float(g.points[v][k]));
    }
    const double len = std::sqrt(double(m.normals[3 * v]) * m.normals[3 * v] +
                                 double(m.normals[3 * v + 1]) * m.normals[3 * v + 1] +
                                 double(m.normals[3 * v + 2]) * m.normals[3 * v + 2]);
    REQUIRE(len == Approx(1).margin(1e-5));
  }
  for (size_t i = 0; i < m.triangleCount(); ++i) {
    const V3 a = g.points[m.indices[3 * i]], b = g.points[m.indices[3 * i + 1]], c = g.points[m.indices[3 * i + 2]];
    const V3 f = cross(sub(b, a), sub(c, a));
    INFO("triangle " << i);
    REQUIRE(norm(f) > 1e-10);  // twice the area, in tile units squared
    for (size_t k = 0; k < 3; ++k) {
      const size_t v = m.indices[3 * i + k];
      const V3 nv{m.normals[3 * v], m.normals[3 * v + 1], m.normals[3 * v + 2]};
      REQUIRE(dot(nv, f) > 0);  // the vertex normal is on the face's front side
    }
  }
}

// Is the end point on exactly one border line? Which coordinate (0 = x, 1 = y), which value.
bool onBorder(Point2 p, int& axis, double& value) {
  const bool vx = p.x == 0 || p.x == 1, vy = p.y == 0 || p.y == 1;
  if (vx == vy) return false;
  axis = vx ? 0 : 1;
  value = vx ? p.x : p.y;
  return true;
}

TileSet singleSymbol(Curve locus, Curve section) {
  TileSet ts;
  ts.loci.push_back({"locus", std::move(locus)});
  ts.sections.push_back({"section", std::move(section)});
  ts.tiles = {Tile{'A', 0, 0}};
  validateTileSet(ts, "test");
  return ts;
}

}  // namespace

TEST_CASE("ornaments of the example tile set stay in the tile, on the plane, below the height", "[evolve][ornament]") {
  const TileSet ts = exampleTileSet();
  const OrnamentOptions opt;
  for (const Allele a : ts.alleles()) {
    INFO("allele " << ts.letters()[a.symbol] << " turned " << int(a.turns));
    const OrnamentGrid g = ornamentGrid(ts, a, opt);
    const fgsg::rt::Mesh m = tileOrnament(ts, a, opt);
    checkWellFormed(g, m);
    for (const V3& p : g.points) {
      CHECK(p[0] >= -1e-12);
      CHECK(p[0] <= 1 + 1e-12);
      CHECK(p[1] >= -1e-12);
      CHECK(p[1] <= 1 + 1e-12);
      CHECK(p[2] >= 0);
      CHECK(p[2] <= opt.height);
    }
    // The section's end points, the ornament's bottom edges, lie on z = 0.
    for (size_t i = 0; i < g.t.size(); ++i) {
      CHECK(g.at(i, 0)[2] == 0);
      CHECK(g.at(i, g.r.size() - 1)[2] == 0);
    }
    // The round section is monotone across, so every face looks up.
    for (size_t i = 0; i < m.triangleCount(); ++i) {
      const V3 p = g.points[m.indices[3 * i]], q = g.points[m.indices[3 * i + 1]], r = g.points[m.indices[3 * i + 2]];
      CHECK(cross(sub(q, p), sub(r, p))[2] > 0);
    }
    // Texture coordinates: u across, v along.
    CHECK(m.texcoords[0] == 0.0f);
    CHECK(m.texcoords[2 * (g.r.size() - 1)] == 1.0f);
    CHECK(m.texcoords[2 * m.vertexCount() - 1] == 1.0f);
  }
}

TEST_CASE("an ornament's end sections lie on the border line where its locus ends", "[evolve][ornament]") {
  const TileSet example = exampleTileSet();
  // A slanted cubic and a polyline meeting the border at angles other than 90 degrees.
  const TileSet slanted = singleSymbol(cubic({{0, 0.3}, {0.4, 0.2}, {0.6, 0.7}, {1, 0.6}}), semicircle());
  const TileSet bent = singleSymbol(polyline({{0.2, 0}, {0.5, 0.5}, {0.3, 1}}), semicircle());
  int ends = 0;
  for (const TileSet* ts : {&example, &slanted, &bent})
    for (const Allele a : ts->alleles()) {
      INFO("allele " << ts->letters()[a.symbol] << " turned " << int(a.turns));
      const OrnamentGrid g = ornamentGrid(*ts, a);
      const auto ends2 = ts->endpoints(a);
      for (int e = 0; e < 2; ++e) {
        int axis = 0;
        double value = 0;
        REQUIRE(onBorder(ends2[size_t(e)], axis, value));
        const size_t i = e == 0 ? 0 : g.t.size() - 1;
        for (size_t j = 0; j < g.r.size(); ++j) CHECK(std::abs(g.at(i, j)[size_t(axis)] - value) <= 1e-12);
        // ... and not only the end section: the rails really cross the tile there.
        CHECK(std::abs(g.at(i, 0)[size_t(1 - axis)] - g.at(i, g.r.size() - 1)[size_t(1 - axis)]) ==
              Approx(2 * OrnamentOptions{}.halfWidth));
        ++ends;
      }
    }
  CHECK(ends == 2 * (8 + 4 + 4));
}

TEST_CASE("the ornaments of neighbouring tiles whose loci share an end point meet exactly", "[evolve][ornament]") {
  const Curve section = semicircle();
  // {left tile's locus, right (or upper) neighbour's locus in its own tile, shift}.
  struct Pair {
    Curve first, second;
    double dx, dy;
  };
  const std::vector<Pair> pairs = {
      {polyline({{0, 0.5}, {1, 0.5}}), polyline({{0, 0.5}, {1, 0.5}}), 1, 0},
      // Different tangents at the shared point (1, 0.6) ~ (0, 0.6): the seam still closes.
      {cubic({{0, 0.3}, {0.4, 0.2}, {0.6, 0.7}, {1, 0.6}}), cubic({{0, 0.6}, {0.3, 0.9}, {0.7, 0.2}, {1, 0.4}}), 1, 0},
      // Vertically: (0.4, 1) on the top border ~ (0.4, 0) on the upper tile's bottom.
      {polyline({{0.1, 0}, {0.6, 0.5}, {0.4, 1}}), cubic({{0.4, 0}, {0.3, 0.3}, {0.8, 0.6}, {1, 0.7}}), 0, 1},
  };
  for (size_t k = 0; k < pairs.size(); ++k) {
    INFO("pair " << k);
    const OrnamentGrid a = ornamentGrid(pairs[k].first, section), b = ornamentGrid(pairs[k].second, section);
    REQUIRE(a.r == b.r);
    for (size_t j = 0; j < a.r.size(); ++j) {
      const V3 p = a.at(a.t.size() - 1, j), q = b.at(0, j);
      CHECK(std::abs(p[0] - (q[0] + pairs[k].dx)) <= 1e-12);
      CHECK(std::abs(p[1] - (q[1] + pairs[k].dy)) <= 1e-12);
      CHECK(std::abs(p[2] - q[2]) <= 1e-12);
    }
  }
  // The paper's tiles: A (quarter arc) ends at (1, 0.5), where B (straight) starts.
  const TileSet ts = exampleTileSet();
  const OrnamentGrid a = ornamentGrid(ts, Allele{0, 0}), b = ornamentGrid(ts, Allele{1, 0});
  for (size_t j = 0; j < a.r.size(); ++j) {
    const V3 p = a.at(a.t.size() - 1, j), q = b.at(0, j);
    CHECK(std::abs(p[0] - (q[0] + 1)) <= 1e-12);
    CHECK(std::abs(p[1] - q[1]) <= 1e-12);
    CHECK(std::abs(p[2] - q[2]) <= 1e-12);
  }
}

TEST_CASE("a straight locus with a round section gives a ridge along the locus at the height", "[evolve][ornament]") {
  OrnamentOptions opt;
  opt.height = 0.15;
  opt.halfWidth = 0.1;
  const OrnamentGrid g = ornamentGrid(polyline({{0, 0.5}, {1, 0.5}}), semicircle(), opt);
  const auto mid = std::find(g.r.begin(), g.r.end(), 0.5);
  REQUIRE(mid != g.r.end());
  const size_t top = size_t(mid - g.r.begin());
  const size_t i = g.t.size() / 2;
  const V3 p = g.at(i, top);
  CHECK(std::abs(p[0] - g.t[i]) <= 1e-12);
  CHECK(std::abs(p[1] - 0.5) <= 1e-12);
  CHECK(std::abs(p[2] - opt.height) <= 1e-12);
  for (size_t ii = 0; ii < g.t.size(); ++ii) {
    CHECK(std::abs(g.at(ii, top)[1] - 0.5) <= 1e-12);
    CHECK(std::abs(g.at(ii, top)[2] - opt.height) <= 1e-12);
    for (size_t j = 0; j < g.r.size(); ++j) CHECK(g.at(ii, j)[2] <= g.at(ii, top)[2]);
  }
  // The rails: the bottom edges run d to either side, the right-hand one (r = 1) below.
  CHECK(std::abs(g.at(i, 0)[1] - 0.6) <= 1e-12);
  CHECK(std::abs(g.at(i, g.r.size() - 1)[1] - 0.4) <= 1e-12);
  // Symmetric section, straight locus: the cross-section is mirror-symmetric about it.
  for (size_t j = 0; j < g.r.size(); ++j) {
    const V3 a = g.at(i, j), b = g.at(i, g.r.size() - 1 - j);
    CHECK(std::abs((a[1] - 0.5) + (b[1] - 0.5)) <= 1e-12);
    CHECK(std::abs(a[2] - b[2]) <= 1e-12);
  }
}

TEST_CASE("a turned allele's ornament is the unturned one turned about the tile's centre", "[evolve][ornament]") {
  const TileSet example = exampleTileSet();
  // A locus ending in the interior, with a polyline corner, on an asymmetric section.
  const TileSet inner = singleSymbol(polyline({{0.2, 0.3}, {0.7, 0.4}, {0.6, 0.8}}),
                                     cubic({{-1, 0}, {-0.8, 1.2}, {0.2, 0.4}, {1, 0}}));
  for (const TileSet* ts : {&example, &inner})
    for (const Allele a : ts->alleles()) {
      INFO("allele " << ts->letters()[a.symbol] << " turned " << int(a.turns));
      const OrnamentGrid turned = ornamentGrid(*ts, a);
      const OrnamentGrid plain = ornamentGrid(*ts, Allele{a.symbol, 0});
      REQUIRE(turned.points.size() == plain.points.size());
      for (size_t v = 0; v < plain.points.size(); ++v) {
        const Point2 q = turnInTile({plain.points[v][0], plain.points[v][1]}, a.turns);
        CHECK(std::abs(turned.points[v][0] - q.x) <= 1e-12);
        CHECK(std::abs(turned.points[v][1] - q.y) <= 1e-12);
        CHECK(std::abs(turned.points[v][2] - plain.points[v][2]) <= 1e-12);
      }
    }
}

TEST_CASE("the triangle intersection check finds a folded ornament", "[evolve][ornament]") {
  const std::array<V3, 3> flat{V3{0, 0, 0}, V3{1, 0, 0}, V3{0, 1, 0}};
  CHECK(trianglesIntersect(flat, {V3{0.2, 0.2, -1}, V3{0.3, 0.2, 1}, V3{0.2, 0.3, 1}}));
  CHECK_FALSE(trianglesIntersect(flat, {V3{0.2, 0.2, 0.1}, V3{0.3, 0.2, 1}, V3{0.2, 0.3, 1}}));
  CHECK_FALSE(trianglesIntersect(flat, {V3{0.8, 0.8, -1}, V3{0.9, 0.8, 1}, V3{0.8, 0.9, 1}}));
  // A section that crosses itself: swept along a line, the surface cuts through itself.
  const Curve zigzag = polyline({{-1, 0}, {0.8, 0.5}, {-0.8, 0.6}, {1, 0}});
  const OrnamentGrid g = ornamentGrid(polyline({{0, 0.5}, {1, 0.5}}), zigzag);
  CHECK(selfIntersections(g, ornamentMesh(g)) > 0);
}

TEST_CASE("ornaments do not intersect themselves", "[evolve][ornament]") {
  const TileSet example = exampleTileSet();
  const TileSet slanted = singleSymbol(cubic({{0, 0.3}, {0.4, 0.2}, {0.6, 0.7}, {1, 0.6}}), semicircle());
  const TileSet bent = singleSymbol(polyline({{0.2, 0}, {0.5, 0.5}, {0.3, 1}}), semicircle());
  for (const TileSet* ts : {&example, &slanted, &bent})
    for (const Allele a : ts->alleles()) {
      INFO("allele " << ts->letters()[a.symbol] << " turned " << int(a.turns));
      const OrnamentGrid g = ornamentGrid(*ts, a);
      const fgsg::rt::Mesh m = ornamentMesh(g);
      checkWellFormed(g, m);
      CHECK(selfIntersections(g, m) == 0);
    }
}

TEST_CASE("every allele of the test tile files has a finite, non-degenerate ornament", "[evolve][ornament]") {
  int sets = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kData)) {
    if (entry.path().extension() != ".json") continue;
    TileSet ts;
    try {
      ts = readTileFile(entry.path().string());
    } catch (const TileFileError&) {
      continue;  // the bad_*.json files are there to fail
    }
    ++sets;
    for (const Allele a : ts.alleles()) {
      INFO(entry.path().filename().string() << " allele " << ts.letters()[a.symbol] << " turned " << int(a.turns));
      const OrnamentGrid g = ornamentGrid(ts, a);
      checkWellFormed(g, ornamentMesh(g));
    }
  }
  CHECK(sets >= 1);
  // Corners and a flat section: loci through the tile's corners keep the normal offset.
  TileSet corners;
  corners.loci = {{"diag", polyline({{0, 0}, {0.5, 0.5}, {1, 1}})}, {"line", polyline({{0, 0.5}, {1, 0.5}})}};
  corners.sections = {{"flat", polyline({{-1, 0}, {1, 0}})}, {"bump", cubic({{-1, 0}, {-0.5, 1}, {0.5, 1}, {1, 0}})}};
  corners.tiles = {Tile{'A', 0, 0}, Tile{'B', 0, 1}, Tile{'C', 1, 0}, Tile{'D', 1, 1}};
  validateTileSet(corners, "corners");
  for (const Allele a : corners.alleles()) {
    INFO("corners allele " << corners.letters()[a.symbol] << " turned " << int(a.turns));
    const OrnamentGrid g = ornamentGrid(corners, a);
    checkWellFormed(g, ornamentMesh(g));
  }
}

TEST_CASE("ornament options out of range are refused", "[evolve][ornament]") {
  const TileSet ts = exampleTileSet();
  auto with = [](auto set) {
    OrnamentOptions o;
    set(o);
    return o;
  };
  CHECK_THROWS_AS(tileOrnament(ts, {}, with([](OrnamentOptions& o) { o.halfWidth = 0; })), std::invalid_argument);
  CHECK_THROWS_AS(tileOrnament(ts, {}, with([](OrnamentOptions& o) { o.height = std::nan(""); })), std::invalid_argument);
  CHECK_THROWS_AS(tileOrnament(ts, {}, with([](OrnamentOptions& o) { o.samplesAlong = 1; })), std::invalid_argument);
  CHECK_THROWS_AS(tileOrnament(ts, {}, with([](OrnamentOptions& o) { o.samplesAcross = 100000; })),
                  std::invalid_argument);
  CHECK(tileOrnament(ts, {}, with([](OrnamentOptions& o) { o.height = 0; })).triangleCount() > 0);
}
