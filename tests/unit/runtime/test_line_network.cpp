// Linear structures (FGSG §4.4): lines clipped where they meet, forks, rollback, the
// segment grid, and the tube meshes swept along lines.
#include "runtime/lines/line_network.h"
#include "runtime/point_grid.h"
#include "runtime/lines/tube.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>

using namespace fgsg::rt;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Within 1e-12 of `expected`, component by component.
void checkPoint(const Vec3& actual, const Vec3& expected, double margin = 1e-12) {
  INFO("actual (" << actual.transpose() << "), expected (" << expected.transpose() << ")");
  for (int k = 0; k < 3; ++k) CHECK(actual[k] == Approx(expected[k]).margin(margin));
}

// A line through `points`, every segment added whole.
LineCursor polyline(LineNetwork& net, const std::vector<Vec3>& points, LineStyle style = {},
                    uint32_t owner = 0) {
  LineCursor c = net.start(points[0], style, owner);
  for (size_t i = 1; i < points.size(); ++i)
    REQUIRE(net.extend(c, points[i]) == SegmentOutcome::Added);
  return c;
}

Vec3 vertex(const fgsg::rt::MeshArray<float>& a, size_t v) {
  return {a[3 * v], a[3 * v + 1], a[3 * v + 2]};
}

Vec3 faceNormal(const Mesh& m, size_t t) {  // unnormalised, from the winding
  const Vec3 a = vertex(m.positions, m.indices[3 * t]);
  const Vec3 b = vertex(m.positions, m.indices[3 * t + 1]);
  const Vec3 c = vertex(m.positions, m.indices[3 * t + 2]);
  return (b - a).cross(c - a);
}

// Signed volume by the divergence theorem: positive when the triangles face outwards.
double signedVolume(const Mesh& m) {
  double vol = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    vol += vertex(m.positions, m.indices[3 * t]).dot(faceNormal(m, t)) / 6.0;
  return vol;
}

// Every undirected edge, with vertices welded by exact position (caps have their own
// vertices), is used by exactly two triangles, once in each direction.
bool watertight(const Mesh& m) {
  std::map<std::array<float, 3>, uint32_t> weld;
  std::vector<uint32_t> id(m.vertexCount());
  for (uint32_t v = 0; v < m.vertexCount(); ++v) {
    const std::array<float, 3> p{m.positions[3 * v], m.positions[3 * v + 1],
                                 m.positions[3 * v + 2]};
    id[v] = weld.emplace(p, uint32_t(weld.size())).first->second;
  }
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      ++directed[{id[m.indices[3 * t + k]], id[m.indices[3 * t + (k + 1) % 3]]}];
  for (const auto& [e, n] : directed) {
    if (n != 1) return false;
    auto back = directed.find({e.second, e.first});
    if (back == directed.end() || back->second != 1) return false;
  }
  return true;
}

// Vertex normals are unit length and on the same side as the winding's face normal.
void checkNormals(const Mesh& m) {
  REQUIRE(m.normals.size() == m.positions.size());
  CHECK(m.colors.empty());
  for (size_t v = 0; v < m.vertexCount(); ++v)
    REQUIRE(vertex(m.normals, v).norm() == Approx(1.0).margin(1e-6));
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const Vec3 n = faceNormal(m, t);
    for (int k = 0; k < 3; ++k) REQUIRE(n.dot(vertex(m.normals, m.indices[3 * t + k])) > 0);
  }
}

// A bent 3D line: a quarter helix.
std::vector<Vec3> helix(int n) {
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const double a = 0.5 * kPi * i / (n - 1);
    p.emplace_back(2 * std::cos(a), 2 * std::sin(a), 0.3 * i);
  }
  return p;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Meeting other lines

TEST_CASE("a merge line crossing another is clipped exactly at the crossing and ends", "[lines]") {
  LineNetwork net;
  polyline(net, {{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  LineCursor b = net.start({0.3, -0.7, 0}, {0.05, true}, 7);
  Vec3 hit(9, 9, 9);
  // Crosses y = 0 at x = 0.3 + 1.0 * 0.7 / 1.6, a fraction 0.4375 along the segment.
  REQUIRE(net.extend(b, {1.3, 0.9, 0}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {0.7375, 0, 0});
  CHECK(b.ended);
  CHECK(b.chain == 1);
  CHECK(b.point == 1);
  REQUIRE(net.points(1).size() == 2);
  checkPoint(net.points(1)[1], {0.7375, 0, 0});
  CHECK(net.points(1)[1] == hit);  // the reported end is the stored one
  CHECK(net.segmentCount() == 4);

  // The line is finished: nothing more is added, and hitPoint is left alone.
  hit = Vec3(9, 9, 9);
  CHECK(net.extend(b, {2, 2, 0}, &hit) == SegmentOutcome::Ended);
  CHECK(hit == Vec3(9, 9, 9));
  CHECK(net.segmentCount() == 4);
  CHECK(net.points(1).size() == 2);
}

TEST_CASE("of several crossings the first along the new segment wins", "[lines]") {
  LineNetwork net;
  polyline(net, {{0, 2, 0}, {4, 2, 0}});  // added first: the lower segment id
  polyline(net, {{0, 1, 0}, {4, 1, 0}});
  LineCursor c = net.start({1, 0, 0}, {0.0, true}, 0);
  Vec3 hit;
  REQUIRE(net.extend(c, {3, 4, 0}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {1.5, 1, 0});  // y = 1 comes before y = 2
}

TEST_CASE("on a tie the segment added first wins", "[lines]") {
  // Two lines 0.02 apart in z cross the probe's path at the same parameter; the probe
  // reaches both and joins the one with the lower segment id.
  for (bool upperFirst : {true, false}) {
    LineNetwork net;
    const std::vector<Vec3> upper = {{0, 0, 0.01}, {2, 0, 0.01}};
    const std::vector<Vec3> lower = {{0, 0, -0.01}, {2, 0, -0.01}};
    polyline(net, upperFirst ? upper : lower);
    polyline(net, upperFirst ? lower : upper);
    LineCursor c = net.start({1, -1, 0}, {0.05, true}, 0);
    Vec3 hit;
    REQUIRE(net.extend(c, {1, 1, 0}, &hit) == SegmentOutcome::Joined);
    CHECK(hit == Vec3(1, 0, upperFirst ? 0.01 : -0.01));
  }
}

TEST_CASE("a non-merge line is stopped and its segment dropped", "[lines]") {
  LineNetwork net;
  polyline(net, {{0, 0, 0}, {2, 0, 0}});
  LineCursor b = net.start({0.5, -1, 0}, {0.05, false}, 0);
  REQUIRE(net.extend(b, {0.5, -0.5, 0}) == SegmentOutcome::Added);
  const LineCursor sibling = b;  // another shape standing at the same point
  Vec3 hit;
  REQUIRE(net.extend(b, {0.5, 0.5, 0}, &hit) == SegmentOutcome::Stopped);
  checkPoint(hit, {0.5, 0, 0});  // where it ran into the other line
  CHECK(b.ended);
  CHECK(b.point == 1);
  CHECK(net.points(1).size() == 2);
  CHECK(net.segmentCount() == 2);
  CHECK(net.extend(b, {1, -1, 0}) == SegmentOutcome::Ended);
  CHECK(net.segmentCount() == 2);

  // Only the cursor that met the line ended: a sibling turning away extends the chain.
  LineCursor turn = sibling;
  REQUIRE(net.extend(turn, {1.5, -0.5, 0}) == SegmentOutcome::Added);
  CHECK(turn.chain == 1);
  CHECK(net.points(1).size() == 3);
}

TEST_CASE("parallel lines meet only within their widths", "[lines]") {
  LineNetwork net;
  polyline(net, {{0, 0, 0}, {2, 0, 0}}, {0.05, true});

  // Centrelines 0.051 apart, reach (0.05 + 0.05) / 2 = 0.05: no contact.
  LineCursor far = net.start({-1, 0.051, 0}, {0.05, true}, 0);
  CHECK(net.extend(far, {3, 0.051, 0}) == SegmentOutcome::Added);

  // 0.049 apart and coming in along the line: joined where the overlap starts, onto the
  // other centreline.
  LineCursor near = net.start({-1, -0.049, 0}, {0.05, true}, 0);
  Vec3 hit;
  REQUIRE(net.extend(near, {1, -0.049, 0}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {0, 0, 0});
}

TEST_CASE("thick lines meet when their tubes touch, however short their segments", "[lines]") {
  LineNetwork net;
  polyline(net, {{0, 0, 0}, {0.1, 0, 0}}, {1.0, true});
  LineCursor b = net.start({0.05, 1.05, 0}, {1.0, true}, 0);
  Vec3 hit;
  // Centres 1.0 apart with segments of 0.1: only the widths bring them within reach.
  REQUIRE(net.extend(b, {0.05, 0.95, 0}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {0.05, 0, 0});
}

TEST_CASE("a near miss is joined onto the other line's centreline", "[lines]") {
  LineNetwork net;
  polyline(net, {{0, 0, 0}, {2, 0, 0}}, {0.05, true});
  LineCursor b = net.start({1.25, -1, 0}, {0.02, true}, 0);
  Vec3 hit;
  // Ends 0.01 short of the centreline, within the reach (0.05 + 0.02) / 2 = 0.035.
  REQUIRE(net.extend(b, {1.25, -0.01, 0}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {1.25, 0, 0});
  checkPoint(net.points(1).back(), {1.25, 0, 0});

  // 0.04 short is out of reach: the segment stays as it is.
  LineCursor c = net.start({0.5, -1, 0}, {0.02, true}, 0);
  REQUIRE(net.extend(c, {0.5, -0.04, 0}, &hit) == SegmentOutcome::Added);
  CHECK(hit == Vec3(0.5, -0.04, 0));
  CHECK(net.points(2).back() == Vec3(0.5, -0.04, 0));

  // Head to head, 0.01 beside it and running 0.02 past its end: joined at that end, though
  // the two segments' centres are a whole segment length apart.
  LineCursor d = net.start({4, 0.01, 0}, {0.05, true}, 0);
  REQUIRE(net.extend(d, {1.98, 0.01, 0}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {2, 0, 0});
}

TEST_CASE("lines on different planes pass over each other", "[lines]") {
  LineNetwork net;
  polyline(net, {{0, 0, 0}, {2, 0, 0}}, {0.1, true});
  LineCursor b = net.start({1, -1, 0.11}, {0.1, true}, 0);
  CHECK(net.extend(b, {1, 1, 0.11}) == SegmentOutcome::Added);
  LineCursor c = net.start({1.5, -1, 0.09}, {0.1, true}, 0);
  Vec3 hit;
  CHECK(net.extend(c, {1.5, 1, 0.09}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {1.5, 0, 0});
}

// ---------------------------------------------------------------------------------------
// Branches and the line itself

TEST_CASE("extending from an inner point forks a new chain that does not hit its parent",
          "[lines]") {
  LineNetwork net;
  const LineStyle thick{0.4, true};  // wide enough to overlap the parent for a while
  LineCursor main = net.start({0, 0, 0}, thick, 42);
  REQUIRE(net.extend(main, {1, 0, 0}) == SegmentOutcome::Added);
  LineCursor branch = main;  // a second shape derived at (1, 0, 0)
  REQUIRE(net.extend(main, {2, 0, 0}) == SegmentOutcome::Added);
  REQUIRE(net.extend(main, {3, 0, 0}) == SegmentOutcome::Added);

  REQUIRE(net.extend(branch, {1.5, 0.3, 0}) == SegmentOutcome::Added);
  CHECK(net.chainCount() == 2);
  CHECK(branch.chain == 1);
  CHECK(branch.point == 1);
  CHECK(net.points(1) == std::vector<Vec3>{{1, 0, 0}, {1.5, 0.3, 0}});
  CHECK(net.style(1).width == 0.4);
  CHECK(net.style(1).merge);
  CHECK(net.owner(1) == 42);
  CHECK(net.points(0).size() == 4);  // the parent is untouched

  REQUIRE(net.extend(branch, {2.5, 0.8, 0}) == SegmentOutcome::Added);  // moving away
  CHECK(branch.chain == 1);  // at its own chain's end now: no further fork
  CHECK(net.chainCount() == 2);

  // The parent is still an obstacle once the branch turns back into it.
  LineNetwork again = net;
  LineCursor back = branch;
  Vec3 hit;
  REQUIRE(again.extend(back, {3.5, -0.5, 0}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {3, 0, 0});  // it passes 0.09 beyond the parent's end
  CHECK(again.points(1).back() == hit);
}

TEST_CASE("a branch crossing its parent is joined at the crossing", "[lines]") {
  LineNetwork net;
  LineCursor main = net.start({0, 0, 0}, {0.0, true}, 0);
  REQUIRE(net.extend(main, {1, 0, 0}) == SegmentOutcome::Added);
  LineCursor branch = main;
  REQUIRE(net.extend(main, {2, 0, 0}) == SegmentOutcome::Added);
  REQUIRE(net.extend(branch, {1.5, 0.3, 0}) == SegmentOutcome::Added);
  Vec3 hit;
  // y = 0.3 - 0.8 u reaches 0 at u = 0.375, x = 1.5 + 0.375.
  REQUIRE(net.extend(branch, {2.5, -0.5, 0}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {1.875, 0, 0});
}

TEST_CASE("a line does not meet its own previous segment but a loop meets itself", "[lines]") {
  LineNetwork net;
  // A sharp turn back runs alongside the previous segment, well within the width.
  LineCursor turn = net.start({0, 0, 0}, {0.2, true}, 0);
  REQUIRE(net.extend(turn, {1, 0, 0}) == SegmentOutcome::Added);
  CHECK(net.extend(turn, {0.2, 0.05, 0}) == SegmentOutcome::Added);
  // Turning back exactly, or all but exactly (where the closest-point formula is at its
  // least accurate), is no contact either.
  LineCursor reverse = net.start({0.3, 3.7, 0}, {0.2, true}, 0);
  REQUIRE(net.extend(reverse, {1.3, 3.8, 0}) == SegmentOutcome::Added);
  CHECK(net.extend(reverse, {0.8, 3.75, 0}) == SegmentOutcome::Added);
  for (double off : {1e-5, 1e-6, 1e-7, 1e-9}) {
    LineNetwork own;
    LineCursor near = own.start({0.3, 1.7 + off, 0}, {0.2, true}, 0);
    REQUIRE(own.extend(near, {1.3, 1.8, 0}) == SegmentOutcome::Added);
    CHECK(own.extend(near, {0.5, 1.72 + 0.3 * off, 0}) == SegmentOutcome::Added);
  }

  // A thick line drawn in short steps around a bend: every earlier segment it is near
  // lies behind it.
  LineCursor arc = net.start({10, 0, 0}, {1.0, true}, 0);
  for (int i = 1; i <= 20; ++i) {
    const double a = 0.05 * i;
    const Vec3 next(10 + 2 * std::sin(a), 2 - 2 * std::cos(a), 0);
    REQUIRE(net.extend(arc, next) == SegmentOutcome::Added);
  }

  LineCursor loop = net.start({0, 5, 0}, {0.05, true}, 0);
  REQUIRE(net.extend(loop, {2, 5, 0}) == SegmentOutcome::Added);
  REQUIRE(net.extend(loop, {2, 6, 0}) == SegmentOutcome::Added);
  REQUIRE(net.extend(loop, {1, 6, 0}) == SegmentOutcome::Added);
  Vec3 hit;
  REQUIRE(net.extend(loop, {1, 4, 0}, &hit) == SegmentOutcome::Joined);
  checkPoint(hit, {1, 5, 0});
  CHECK(net.points(loop.chain).size() == 5);
}

TEST_CASE("zero-length and non-finite segments are ignored, invalid cursors are ended",
          "[lines]") {
  LineNetwork net;
  LineCursor c = net.start({1, 2, 3}, {}, 0);
  Vec3 hit;
  CHECK(net.extend(c, {1, 2, 3}, &hit) == SegmentOutcome::Added);
  CHECK(hit == Vec3(1, 2, 3));
  CHECK(net.extend(c, {NAN, 0, 0}) == SegmentOutcome::Added);
  CHECK(net.extend(c, {INFINITY, 0, 0}) == SegmentOutcome::Added);
  CHECK(net.segmentCount() == 0);
  CHECK(c.point == 0);
  CHECK_FALSE(c.ended);

  LineCursor none;
  CHECK_FALSE(none.valid());
  CHECK(net.extend(none, {0, 0, 0}) == SegmentOutcome::Ended);
  CHECK(net.segmentCount() == 0);
}

// ---------------------------------------------------------------------------------------
// Rollback and the grid

TEST_CASE("rollback removes everything added after the mark", "[lines]") {
  LineNetwork net;
  LineCursor a = net.start({0, 0, 0}, {0.05, true}, 1);
  REQUIRE(net.extend(a, {1, 0, 0}) == SegmentOutcome::Added);
  LineCursor fork = a;
  REQUIRE(net.extend(a, {2, 0, 0}) == SegmentOutcome::Added);
  const LineCursor before = a;

  const size_t mark = net.mark();
  net.rollback(mark);  // nothing to undo
  CHECK(net.chainCount() == 1);
  CHECK(net.segmentCount() == 2);

  REQUIRE(net.extend(a, {3, 0, 0}) == SegmentOutcome::Added);           // grows an old chain
  REQUIRE(net.extend(fork, {1, 1, 0}) == SegmentOutcome::Added);         // forks a new one
  polyline(net, {{0, 3, 0}, {0, 4, 0}, {0, 5, 0}});                      // and a new line
  CHECK(net.chainCount() == 3);
  CHECK(net.segmentCount() == 6);

  net.rollback(mark);
  CHECK(net.chainCount() == 1);
  CHECK(net.segmentCount() == 2);
  CHECK(net.points(0) == std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  CHECK(net.mark() == mark);

  // What was removed is no obstacle any more; what stayed still is.
  LineCursor probe = net.start({2.5, -1, 0}, {0.05, true}, 0);
  CHECK(net.extend(probe, {2.5, 1, 0}) == SegmentOutcome::Added);
  LineCursor probe2 = net.start({-1, 4, 0}, {0.05, true}, 0);
  CHECK(net.extend(probe2, {1, 4, 0}) == SegmentOutcome::Added);
  LineCursor probe3 = net.start({1.5, -1, 0}, {0.05, true}, 0);
  CHECK(net.extend(probe3, {1.5, 1, 0}) == SegmentOutcome::Joined);

  // The old chain grows again from where it was, with the same result as before.
  LineCursor again = before;
  CHECK(net.extend(again, {3, 0, 0}) == SegmentOutcome::Joined);  // now crosses probe at 2.5
  checkPoint(net.points(0).back(), {2.5, 0, 0});
}

TEST_CASE("the segment grid reports the entries within a radius, ascending", "[lines]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-10, 10);
  std::vector<Vec3> centres;
  PointGrid grid;
  grid.reserveRadius(0.5);
  for (int i = 0; i < 400; ++i) {
    centres.emplace_back(u(rng), u(rng), u(rng) * 0.1);
    CHECK(grid.add(centres.back()) == uint32_t(i));
  }
  auto brute = [&](const Vec3& p, double r) {
    std::vector<uint32_t> ids;
    for (uint32_t i = 0; i < centres.size(); ++i)
      if ((centres[i] - p).norm() <= r) ids.push_back(i);
    return ids;
  };
  std::vector<uint32_t> found;
  size_t total = 0;
  for (double r : {0.5, 1.7, 3.0}) {
    grid.reserveRadius(r);
    CHECK(grid.cellSize() >= r);
    for (int q = 0; q < 50; ++q) {
      const Vec3 p(u(rng), u(rng), 0);
      grid.near(p, r, found);
      CHECK(found == brute(p, r));
      total += found.size();
    }
  }
  CHECK(total > 0);

  // Removing the newest entries: they are no longer reported.
  for (int i = 0; i < 100; ++i) {
    grid.removeLast();
    centres.pop_back();
  }
  CHECK(grid.size() == 300);
  for (int q = 0; q < 50; ++q) {
    const Vec3 p(u(rng), u(rng), 0);
    grid.near(p, 3.0, found);
    CHECK(found == brute(p, 3.0));
  }
}

// ---------------------------------------------------------------------------------------
// Determinism

namespace {

struct Probe {
  SegmentOutcome outcome;
  Vec3 end;
};

// Builds the network with the given lines in the given order, then grows a probe line.
Probe runProbe(const std::vector<std::vector<Vec3>>& lines, const std::vector<int>& order,
               bool farLongSegment) {
  LineNetwork net;
  if (farLongSegment) polyline(net, {{1000, 1000, 0}, {1100, 1000, 0}});  // grows the cells
  for (int i : order) {
    // Line 0 ends where line 1 starts: added after it, it joins it there, the same end.
    LineCursor c = net.start(lines[i][0], {0.05, true}, 0);
    for (size_t k = 1; k < lines[i].size(); ++k) net.extend(c, lines[i][k]);
    REQUIRE(net.points(c.chain) == lines[i]);
  }
  LineCursor probe = net.start({1, -1, 0}, {0.05, true}, 0);
  Probe p;
  p.outcome = net.extend(probe, {1, 3, 0}, &p.end);
  return p;
}

}  // namespace

TEST_CASE("results do not depend on the order of unrelated lines or the grid's cells",
          "[lines]") {
  // Two lines meeting at (1, 0.5), and one further on: the probe reaches the meeting point
  // first, at the same parameter on both (the tie goes to the lower id), then y = 2.
  const std::vector<std::vector<Vec3>> lines = {
      {{0, 0.5, 0}, {1, 0.5, 0}}, {{1, 0.5, 0}, {2, 1, 0}}, {{-1, 2, 0}, {0.5, 2, 0}, {3, 2, 0}}};
  const Probe ref = runProbe(lines, {0, 1, 2}, false);
  REQUIRE(ref.outcome == SegmentOutcome::Joined);
  checkPoint(ref.end, {1, 0.5, 0});
  for (const auto& order : std::vector<std::vector<int>>{{2, 1, 0}, {1, 0, 2}, {2, 0, 1}})
    for (bool far : {false, true}) {
      const Probe p = runProbe(lines, order, far);
      CHECK(p.outcome == ref.outcome);
      CHECK(p.end == ref.end);  // bit for bit
    }
}

TEST_CASE("random walks meet the same lines whatever the grid's cell size", "[lines]") {
  // With a far segment of length 500 first, the grid's cells are so large that every
  // query sees every segment: the hash grid must not lose or add any meeting.
  auto grow = [](bool hugeCells) {
    LineNetwork net;
    if (hugeCells) polyline(net, {{1e4, 0, 0}, {1e4 + 500, 0, 0}});
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<SegmentOutcome> outcomes;
    for (int line = 0; line < 40; ++line) {
      Vec3 p(5 * u(rng), 5 * u(rng), 0.2 * u(rng));
      LineCursor c = net.start(p, {0.05 + 0.1 * (u(rng) + 1), line % 3 != 0}, line);
      Vec3 dir(u(rng), u(rng), 0.1 * u(rng));
      for (int step = 0; step < 30; ++step) {
        dir = (dir + 0.4 * Vec3(u(rng), u(rng), 0.1 * u(rng))).normalized();
        p += (0.05 + 0.3 * (u(rng) + 1)) * dir;
        outcomes.push_back(net.extend(c, p));
      }
    }
    std::vector<std::vector<Vec3>> lines;
    for (uint32_t k = hugeCells ? 1 : 0; k < net.chainCount(); ++k) lines.push_back(net.points(k));
    return std::make_pair(outcomes, lines);
  };
  const auto fine = grow(false), coarse = grow(true);
  CHECK(fine.first == coarse.first);
  CHECK(fine.second == coarse.second);
  // The walks do meet: all four outcomes occur.
  for (SegmentOutcome o : {SegmentOutcome::Added, SegmentOutcome::Joined, SegmentOutcome::Stopped,
                           SegmentOutcome::Ended})
    CHECK(std::count(fine.first.begin(), fine.first.end(), o) > 0);
}

// ---------------------------------------------------------------------------------------
// Tubes

TEST_CASE("the centreline passes exactly through the line's points", "[lines]") {
  const std::vector<Vec3> points = helix(5);
  const std::vector<Vec3> samples = sampleCentreline(points, 6);
  REQUIRE(samples.size() == 4 * 6 + 1);
  for (size_t i = 0; i < points.size(); ++i) CHECK(samples[6 * i] == points[i]);
  // Smooth: consecutive samples are close to evenly spaced, none doubles back.
  for (size_t i = 1; i + 1 < samples.size(); ++i) {
    const Vec3 d0 = samples[i] - samples[i - 1], d1 = samples[i + 1] - samples[i];
    CHECK(d0.dot(d1) > 0.9 * d0.norm() * d1.norm());
  }
  // A straight line stays straight.
  const std::vector<Vec3> straight = sampleCentreline({{0, 0, 0}, {1, 1, 0}, {3, 3, 0}}, 4);
  for (const Vec3& s : straight) CHECK(s.x() == Approx(s.y()).margin(1e-12));
  CHECK(sampleCentreline({{1, 2, 3}}, 4).size() == 1);
}

TEST_CASE("a straight tube has the expected size, winding and volume", "[lines]") {
  LineNetwork net;
  polyline(net, {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}}, {0.2, true});
  const int sides = 8, per = 4;
  const Mesh m = net.sweep(0, sides, per);
  const size_t samples = 2 * per + 1;
  CHECK(m.vertexCount() == samples * sides + 2 * (sides + 1));
  CHECK(m.triangleCount() == 2 * sides * samples);
  CHECK(watertight(m));
  checkNormals(m);
  const double r = 0.1, length = 3;
  const double polygonArea = 0.5 * sides * r * r * std::sin(2 * kPi / sides);
  CHECK(signedVolume(m) == Approx(polygonArea * length).epsilon(1e-5));
  CHECK(m.boundsMin()[0] == 0.0f);
  CHECK(m.boundsMax()[0] == 3.0f);

  // Many sides approach the cylinder.
  const Mesh round = net.sweep(0, 64, 1);
  CHECK(signedVolume(round) == Approx(kPi * r * r * length).epsilon(0.005));
  CHECK(signedVolume(round) < kPi * r * r * length);
}

TEST_CASE("tube rings lie at the radius around the centreline, ends on the endpoints", "[lines]") {
  LineNetwork net;
  const std::vector<Vec3> points = helix(6);
  polyline(net, points, {0.3, true});
  const int sides = 7, per = 5;
  const Mesh m = net.sweep(0, sides, per);
  const std::vector<Vec3> samples = sampleCentreline(points, per);
  REQUIRE(m.vertexCount() == samples.size() * sides + 2 * (sides + 1));
  CHECK(watertight(m));
  checkNormals(m);
  CHECK(signedVolume(m) > 0);
  for (size_t i = 0; i < samples.size(); ++i) {
    Vec3 mean = Vec3::Zero();
    for (int k = 0; k < sides; ++k) {
      const Vec3 v = vertex(m.positions, i * sides + k);
      CHECK((v - samples[i]).norm() == Approx(0.15).epsilon(1e-5));
      // The ring is square to the centreline: its offsets are perpendicular to the chord
      // through the neighbouring samples.
      const Vec3 chord = samples[std::min(i + 1, samples.size() - 1)] - samples[i > 0 ? i - 1 : 0];
      CHECK(std::abs((v - samples[i]).dot(chord.normalized())) < 1e-5);
      mean += v / sides;
    }
    checkPoint(mean, samples[i], 1e-6);
  }
  // First and last rings, and the caps' centres, sit on the chain's endpoints.
  const size_t startCap = samples.size() * sides, endCap = startCap + sides + 1;
  CHECK(vertex(m.positions, startCap) == Vec3(points.front().cast<float>().cast<double>()));
  CHECK(vertex(m.positions, endCap) == Vec3(points.back().cast<float>().cast<double>()));
  Vec3 first = Vec3::Zero(), last = Vec3::Zero();
  for (int k = 0; k < sides; ++k) {
    first += vertex(m.positions, k) / sides;
    last += vertex(m.positions, (samples.size() - 1) * sides + k) / sides;
  }
  checkPoint(first, points.front(), 1e-6);
  checkPoint(last, points.back(), 1e-6);
}

TEST_CASE("a tube along a planar line does not twist", "[lines]") {
  // An S-bend in z = 0: parallel transport turns the frames about Z only, so each ring
  // vertex keeps its height above the plane.
  LineNetwork net;
  polyline(net, {{0, 0, 0}, {1, 0.2, 0}, {2, 1, 0}, {2.5, 2, 0}, {3.5, 2.6, 0}, {5, 2.5, 0}},
           {0.2, true});
  const int sides = 6, per = 4;
  const Mesh m = net.sweep(0, sides, per);
  const size_t rings = 5 * per + 1;
  double maxHeight = 0;
  for (int k = 0; k < sides; ++k) {
    const double z0 = m.positions[3 * k + 2];
    maxHeight = std::max(maxHeight, std::abs(z0));
    for (size_t i = 1; i < rings; ++i)
      CHECK(m.positions[3 * (i * sides + k) + 2] == Approx(z0).margin(1e-6));
  }
  CHECK(maxHeight == Approx(0.1).epsilon(1e-6));
  CHECK(watertight(m));
  checkNormals(m);
}

TEST_CASE("a tube along a helix turns its rings by the least rotation", "[lines]") {
  // From ring to ring the frame turns only as much as the centreline does: carrying ring
  // i's first offset by the least rotation between the two rings' planes gives ring i+1's.
  // (Frames rebuilt from a fixed "up" axis twist by up to 1.8 radians here.)
  LineNetwork net;
  polyline(net, helix(6), {0.3, true});
  const int sides = 7;
  const Mesh m = net.sweep(0, sides, 5);
  const size_t rings = 5 * 5 + 1;
  auto offset = [&](size_t i, int k) {
    Vec3 mean = Vec3::Zero();
    for (int j = 0; j < sides; ++j) mean += vertex(m.positions, i * sides + j) / sides;
    return Vec3(vertex(m.positions, i * sides + k) - mean);
  };
  double worst = 0;
  for (size_t i = 0; i + 1 < rings; ++i) {
    const Vec3 n0 = offset(i, 0).normalized(), n1 = offset(i + 1, 0).normalized();
    const Vec3 t0 = n0.cross(offset(i, 1)).normalized();
    const Vec3 t1 = n1.cross(offset(i + 1, 1)).normalized();
    const Eigen::Quaterniond least = Eigen::Quaterniond::FromTwoVectors(t0, t1);
    const Vec3 carried = least * n0;
    worst = std::max(worst, std::abs(std::atan2(carried.cross(n1).dot(t1), carried.dot(n1))));
  }
  CHECK(worst < 1e-3);
}

TEST_CASE("a joined line's tube ends on the other line's centreline", "[lines]") {
  LineNetwork net;
  polyline(net, {{0, 0, 0}, {2, 0, 0}}, {0.1, true});
  LineCursor b = net.start({1, -2, 0}, {0.1, true}, 0);
  REQUIRE(net.extend(b, {1.2, -1, 0}) == SegmentOutcome::Added);
  REQUIRE(net.extend(b, {1.1, -0.02, 0}) == SegmentOutcome::Joined);
  const Mesh m = net.sweep(b.chain, 8, 3);
  const size_t samples = 2 * 3 + 1;
  Vec3 last = Vec3::Zero();
  for (int k = 0; k < 8; ++k) last += vertex(m.positions, (samples - 1) * 8 + k) / 8;
  checkPoint(last, net.points(b.chain).back(), 1e-6);
  CHECK(std::abs(net.points(b.chain).back().y()) < 1e-15);
  CHECK(watertight(m));
}

TEST_CASE("chains of one point and lines without width sweep to nothing", "[lines]") {
  LineNetwork net;
  net.start({0, 0, 0}, {0.1, true}, 0);
  CHECK(net.sweep(0).empty());
  polyline(net, {{0, 0, 0}, {1, 0, 0}}, {0.0, true});
  CHECK(net.sweep(1).empty());
  polyline(net, {{0, 0, 0}, {1, 0, 0}}, {-1.0, true});
  CHECK(net.style(2).width == 0.0);
  CHECK(net.sweep(2).empty());
  // Three sides at least: 2 * 3 * 2 triangles.
  CHECK(sweepTube({{0, 0, 0}, {1, 0, 0}}, 0.1, 2, 1).triangleCount() == 12);
}
