// CityEngine's insertAlongUV (issue #44; runtime/cga/insert_along_uv.cpp): the built-in unit
// cube laid along faces whose uvs are given by hand, the results' corners, volumes and areas
// worked out by hand in each case.
#include "runtime/assets.h"
#include "runtime/cga/insert_along_uv.h"
#include "runtime/cga/polygon_clip.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <string>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

constexpr double kAlongUvTol = 1e-9;
const std::array<double, 6> kUnitSourceBox{0, 0, 0, 1, 1, 1};

Mesh alongUvCube() {
  Mesh cube;
  REQUIRE(makeBuiltinPrimitive("cube", cube));
  return cube;
}

// Divergence theorem over the faces: the volume of a closed surface whose faces look out.
double alongUvVolume(const std::vector<std::vector<Vec3>>& faces) {
  double v = 0.0;
  for (const auto& f : faces) v += f[0].dot(0.5 * newellNormal(f)) / 3.0;
  return v;
}

double alongUvArea(const std::vector<std::vector<Vec3>>& faces) {
  double a = 0.0;
  for (const auto& f : faces) a += 0.5 * newellNormal(f).norm();
  return a;
}

bool alongUvNear(const Vec3& a, const Vec3& b) { return (a - b).cwiseAbs().maxCoeff() <= kAlongUvTol; }

// Every corner of the result satisfies `allowed`, and every one of `required` is a corner.
void alongUvCornersAre(const std::vector<std::vector<Vec3>>& faces, const std::function<bool(const Vec3&)>& allowed,
                       const std::vector<Vec3>& required) {
  for (const auto& f : faces)
    for (const Vec3& p : f) {
      INFO("corner " << p.transpose());
      CHECK(allowed(p));
    }
  for (const Vec3& r : required) {
    bool found = false;
    for (const auto& f : faces)
      for (const Vec3& p : f) found = found || alongUvNear(p, r);
    INFO("expected corner " << r.transpose());
    CHECK(found);
  }
}

// Every corner of the result is one of `expected`, and each of them is a corner.
void alongUvCornersAre(const std::vector<std::vector<Vec3>>& faces, const std::vector<Vec3>& expected) {
  alongUvCornersAre(
      faces,
      [&](const Vec3& p) {
        return std::any_of(expected.begin(), expected.end(), [&](const Vec3& e) { return alongUvNear(p, e); });
      },
      expected);
}

bool alongUvIn(double x, std::initializer_list<double> values) {
  return std::any_of(values.begin(), values.end(), [&](double v) { return std::abs(x - v) <= kAlongUvTol; });
}

bool alongUvWithin(double x, double lo, double hi) { return x >= lo - kAlongUvTol && x <= hi + kAlongUvTol; }

// A quad lying on the ground (its normal +y), x from x0 to x1 and z from 0 to depth, with
// u = u0 + (x - x0) / tileU and v = v0 + z / tileV.
AlongUvFace alongUvGroundQuad(double x0, double x1, double depth, double u0, double tileU, double v0, double tileV) {
  AlongUvFace f;
  f.corners = {{x0, 0, 0}, {x0, 0, depth}, {x1, 0, depth}, {x1, 0, 0}};
  for (const Vec3& c : f.corners) f.uvs.push_back({u0 + (c.x() - x0) / tileU, v0 + c.z() / tileV});
  return f;
}

std::vector<Vec3> alongUvGrid(const std::vector<double>& xs, const std::vector<double>& ys,
                              const std::vector<double>& zs) {
  std::vector<Vec3> out;
  for (double x : xs)
    for (double y : ys)
      for (double z : zs) out.emplace_back(x, y, z);
  return out;
}

// Every corner lies on a face of the grid's boxes (within the grid, on one of its planes:
// where the input's cuts cross the boxes' faces there are more corners than the grid's),
// and every corner of the grid is one.
void alongUvCornersOnGridFaces(const std::vector<std::vector<Vec3>>& faces, const std::vector<double>& xs,
                               const std::vector<double>& ys, const std::vector<double>& zs) {
  const auto on = [](double x, const std::vector<double>& values) {
    return std::any_of(values.begin(), values.end(), [&](double v) { return std::abs(x - v) <= kAlongUvTol; });
  };
  const auto within = [](double x, const std::vector<double>& values) {
    return alongUvWithin(x, values.front(), values.back());
  };
  alongUvCornersAre(
      faces,
      [&](const Vec3& p) {
        return within(p.x(), xs) && within(p.y(), ys) && within(p.z(), zs) &&
               (on(p.x(), xs) || on(p.y(), ys) || on(p.z(), zs));
      },
      alongUvGrid(xs, ys, zs));
}

}  // namespace

TEST_CASE("insertAlongUV: a unit cube along a straight 10 x 2 quad tiled every 2.5 m", "[cga][insert_along_uv]") {
  // u = x / 2.5 runs 0..4: four copies, each 2.5 m along x, the quad's 2 m across (v 0..1)
  // and 0.5 m high: boxes of 2.5 x 0.5 x 2 = 2.5 m3, 10 m3 in all; each box's surface
  // 2 (2.5 x 0.5 + 2.5 x 2 + 0.5 x 2) = 14.5 m2, 58 m2 in all.
  AlongUvOptions options;
  options.height = 0.5;
  std::vector<std::vector<Vec3>> out;
  std::string error;
  REQUIRE(insertAlongUvFaces({alongUvGroundQuad(0, 10, 2, 0, 2.5, 0, 2)}, alongUvCube(), kUnitSourceBox, options, out,
                             error));
  CHECK(std::abs(alongUvVolume(out) - 10.0) <= kAlongUvTol);
  CHECK(std::abs(alongUvArea(out) - 58.0) <= kAlongUvTol);
  const auto corners = alongUvGrid({0, 2.5, 5, 7.5, 10}, {0, 0.5}, {0, 2});
  alongUvCornersAre(out, corners);

  SECTION("heights along the vertex normals of a flat quad are its normal's: the same boxes") {
    options.vertexNormals = true;
    REQUIRE(insertAlongUvFaces({alongUvGroundQuad(0, 10, 2, 0, 2.5, 0, 2)}, alongUvCube(), kUnitSourceBox, options,
                               out, error));
    CHECK(std::abs(alongUvVolume(out) - 10.0) <= kAlongUvTol);
    CHECK(std::abs(alongUvArea(out) - 58.0) <= kAlongUvTol);
    // The quad is cut into two triangles along a diagonal, which cuts the boxes' faces where
    // it crosses them: more corners, each on a box's face.
    alongUvCornersOnGridFaces(out, {0, 2.5, 5, 7.5, 10}, {0, 0.5}, {0, 2});
  }
  SECTION("a negative height hangs the boxes below the quad, their faces still looking out") {
    options.height = -0.5;
    REQUIRE(insertAlongUvFaces({alongUvGroundQuad(0, 10, 2, 0, 2.5, 0, 2)}, alongUvCube(), kUnitSourceBox, options,
                               out, error));
    CHECK(std::abs(alongUvVolume(out) - 10.0) <= kAlongUvTol);
    alongUvCornersAre(out, alongUvGrid({0, 2.5, 5, 7.5, 10}, {0, -0.5}, {0, 2}));
  }
  SECTION("keepPosition scales the asset's height about its file's own y = 0") {
    // The file's box runs y -1..1 (2 high): with height 1 the asset spans h -0.5..0.5.
    options.height = 1.0;
    options.keepPosition = true;
    REQUIRE(insertAlongUvFaces({alongUvGroundQuad(0, 10, 2, 0, 2.5, 0, 2)}, alongUvCube(), {0, -1, 0, 1, 1, 1},
                               options, out, error));
    CHECK(std::abs(alongUvVolume(out) - 20.0) <= kAlongUvTol);
    alongUvCornersAre(out, alongUvGrid({0, 2.5, 5, 7.5, 10}, {-0.5, 0.5}, {0, 2}));
  }
}

TEST_CASE("insertAlongUV: a unit cube bent over a crease whose uvs run along the surface", "[cga][insert_along_uv]") {
  // Two 5 x 2 quads meeting at a ridge: one rises from (0, 0) to (4, 3) (slope 3/4), the
  // other falls from (4, 3) to (8, 0), z 0..2. u = s / 2 with s the length along the
  // surface (0..10 m, the ridge at s = 5, u = 2.5), v = z / 2. Five copies, 2 m of s each;
  // the third (s 4..6) is bent over the ridge. Heights 0.5 up (scope.y): each 1 m of s
  // moves 0.8 m in x, so each copy is a sheared box of 2 x 0.8 x 0.5 x 2 ... volume
  // |(1.6, +-1.2, 0) . ((0, 0, 2) x (0, 0.5, 0))| = 1.6 m3, 8 m3 in all. Surface of each: top
  // and bottom 2 x 2 = 4 m2 each (measured on the slope), the z faces 1.6 x 0.5 = 0.8 m2
  // each, the ends 2 x 0.5 = 1 m2 each: 11.6 m2, 58 m2 in all.
  AlongUvFace rise, fall;
  rise.corners = {{0, 0, 0}, {0, 0, 2}, {4, 3, 2}, {4, 3, 0}};
  rise.uvs = {{0, 0}, {0, 1}, {2.5, 1}, {2.5, 0}};
  fall.corners = {{4, 3, 0}, {4, 3, 2}, {8, 0, 2}, {8, 0, 0}};
  fall.uvs = {{2.5, 0}, {2.5, 1}, {5, 1}, {5, 0}};
  AlongUvOptions options;
  options.height = 0.5;
  std::vector<std::vector<Vec3>> out;
  std::string error;
  REQUIRE(insertAlongUvFaces({rise, fall}, alongUvCube(), kUnitSourceBox, options, out, error));
  CHECK(std::abs(alongUvVolume(out) - 8.0) <= kAlongUvTol);
  CHECK(std::abs(alongUvArea(out) - 58.0) <= kAlongUvTol);
  // The point s along the surface.
  auto at = [](double s) { return s <= 5 ? Vec3(0.8 * s, 0.6 * s, 0) : Vec3(4 + 0.8 * (s - 5), 3 - 0.6 * (s - 5), 0); };
  std::vector<Vec3> required;
  for (double s : {0.0, 2.0, 4.0, 6.0, 8.0, 10.0})
    for (double y : {0.0, 0.5})
      for (double z : {0.0, 2.0}) required.push_back(at(s) + Vec3(0, y, z));
  // The bent copy's faces are cut at the ridge (x = 4): its corners there, and where the
  // cut crosses its faces' diagonals (the bottom and top at z = 1, the sides part way up).
  for (double y : {0.0, 0.5})
    for (double z : {0.0, 2.0}) required.push_back(at(5) + Vec3(0, y, z));
  alongUvCornersAre(
      out,
      [&](const Vec3& p) {
        for (double s : {0.0, 2.0, 4.0, 6.0, 8.0, 10.0})
          for (double y : {0.0, 0.5})
            for (double z : {0.0, 2.0})
              if (alongUvNear(p, at(s) + Vec3(0, y, z))) return true;
        const bool onRidge = alongUvIn(p.x(), {4}) && alongUvWithin(p.y(), 3, 3.5);
        return onRidge && (alongUvIn(p.z(), {0, 2}) || (alongUvIn(p.z(), {1}) && alongUvIn(p.y(), {3, 3.5})));
      },
      required);

  SECTION("copies meeting on the ridge: the asset's end faces there go to one face each, not both") {
    // u = s / 2.5: four copies of 2.5 m of s, two on each side, their ends on the ridge
    // (u = 2). Each: volume 2.5 x 0.8 x 0.5 x 2 = 2 m3; top and bottom 5 m2 each, the z faces
    // 2 x 0.5 = 1 m2 each, the ends 1 m2 each: 14 m2. In all 8 m3 and 56 m2, no cut.
    for (auto* f : {&rise, &fall})
      for (auto& uv : f->uvs) uv[0] *= 2.0 / 2.5;
    REQUIRE(insertAlongUvFaces({rise, fall}, alongUvCube(), kUnitSourceBox, options, out, error));
    CHECK(std::abs(alongUvVolume(out) - 8.0) <= kAlongUvTol);
    CHECK(std::abs(alongUvArea(out) - 56.0) <= kAlongUvTol);
    std::vector<Vec3> corners;
    for (double s : {0.0, 2.5, 5.0, 7.5, 10.0})
      for (double y : {0.0, 0.5})
        for (double z : {0.0, 2.0}) corners.push_back(at(s) + Vec3(0, y, z));
    alongUvCornersAre(out, corners);
  }
}

TEST_CASE("insertAlongUV: a unit cube bent around an annulus sector in three quads", "[cga][insert_along_uv]") {
  // The ring between radii 4 and 6 from 0 to 90 degrees on the ground, as three quads of 30
  // degrees; u counts the quads (0..3) around, v runs 0 inside to 1 outside. A quad is a
  // trapezoid and its uvs a unit square, not an affine image of it: it is cut into two
  // triangles. Each copy of the cube fills one quad, 0.5 high: quad area
  // 1/2 sin 30 (6^2 - 4^2) = 5, volume 3 x 5 x 0.5 = 7.5. Surface: tops and bottoms 2 x 15,
  // the ends of each copy (radial, 2 x 0.5) 6 x 1, the inner and outer walls along the
  // chords 3 x 0.5 (2 x 4 sin 15 + 2 x 6 sin 15): 36 + 30 sin 15 m2.
  const double pi = std::acos(-1.0);
  auto ring = [&](double r, int k) { return Vec3(r * std::cos(k * pi / 6), 0, r * std::sin(k * pi / 6)); };
  std::vector<AlongUvFace> faces;
  for (int k = 0; k < 3; ++k) {
    AlongUvFace f;  // counter-clockwise seen from above (+y): inner k, inner k + 1, outer k + 1, outer k
    f.corners = {ring(4, k), ring(4, k + 1), ring(6, k + 1), ring(6, k)};
    f.uvs = {{double(k), 0}, {double(k + 1), 0}, {double(k + 1), 1}, {double(k), 1}};
    REQUIRE(newellNormal(f.corners).y() > 0);
    faces.push_back(f);
  }
  AlongUvOptions options;
  options.height = 0.5;
  std::vector<std::vector<Vec3>> out;
  std::string error;
  REQUIRE(insertAlongUvFaces(faces, alongUvCube(), kUnitSourceBox, options, out, error));
  CHECK(std::abs(alongUvVolume(out) - 7.5) <= kAlongUvTol);
  CHECK(std::abs(alongUvArea(out) - (36.0 + 30.0 * std::sin(pi / 12))) <= kAlongUvTol);
  std::vector<Vec3> corners;
  for (int k = 0; k <= 3; ++k)
    for (double r : {4.0, 6.0})
      for (double y : {0.0, 0.5}) corners.push_back(ring(r, k) + Vec3(0, y, 0));
  // Every corner lies on a box: at a quad's corner, or on a quad's diagonal (the cut).
  alongUvCornersAre(
      out,
      [&](const Vec3& p) {
        if (!alongUvIn(p.y(), {0, 0.5}) && !std::any_of(corners.begin(), corners.end(), [&](const Vec3& c) {
              return std::abs(p.x() - c.x()) <= kAlongUvTol && std::abs(p.z() - c.z()) <= kAlongUvTol;
            }))
          return false;
        const double r = std::hypot(p.x(), p.z());
        return alongUvWithin(r, 4 * std::cos(pi / 12), 6) && alongUvWithin(p.x(), 0, 6) && alongUvWithin(p.z(), 0, 6);
      },
      corners);
}

TEST_CASE("insertAlongUV: uvs past the asset's v range and part tiles cut it", "[cga][insert_along_uv]") {
  // x 0..3.5 with u = 0.5 + x / 2 (0.5..2.25), z 0..1.5 with v = 0.25 + z / 2 (0.25..1):
  // the asset fills all of it (v 0..1 covers v 0.25..1; the copies at u 0, 1 and 2 are cut
  // at the ends), its tile edges at u 1 and 2: x 1 and 3.
  AlongUvOptions options;
  options.height = 0.5;
  std::vector<std::vector<Vec3>> out;
  std::string error;
  REQUIRE(insertAlongUvFaces({alongUvGroundQuad(0, 3.5, 1.5, 0.5, 2, 0.25, 2)}, alongUvCube(), kUnitSourceBox,
                             options, out, error));
  // Corners on the boxes' faces (the cuts at x = 3.5 cross their diagonals: more corners).
  alongUvCornersOnGridFaces(out, {0, 1, 3, 3.5}, {0, 0.5}, {0, 1.5});
  // Cut open where the uvs end: the top alone covers the quad, 3.5 x 1.5.
  double top = 0.0;
  for (const auto& f : out)
    if (std::all_of(f.begin(), f.end(), [](const Vec3& p) { return std::abs(p.y() - 0.5) <= kAlongUvTol; }))
      top += 0.5 * newellNormal(f).norm();
  CHECK(std::abs(top - 5.25) <= kAlongUvTol);
}

TEST_CASE("insertAlongUV: the cases it refuses", "[cga][insert_along_uv]") {
  AlongUvOptions options;
  options.height = 0.5;
  std::vector<std::vector<Vec3>> out;
  std::string error;
  SECTION("two faces whose uvs overlap") {
    AlongUvFace a = alongUvGroundQuad(0, 2, 2, 0, 2, 0, 2), b = alongUvGroundQuad(5, 7, 2, 0.5, 2, 0, 2);
    CHECK_FALSE(insertAlongUvFaces({a, b}, alongUvCube(), kUnitSourceBox, options, out, error));
    CHECK(error.find("the uvs of faces 0 and 1 overlap") != std::string::npos);
  }
  SECTION("uvs outside v 0..1") {
    CHECK_FALSE(insertAlongUvFaces({alongUvGroundQuad(0, 2, 2, 0, 2, 2, 2)}, alongUvCube(), kUnitSourceBox, options, out,
                                   error));
    CHECK(error.find("the shape's v runs from 2 to 3") != std::string::npos);
  }
  SECTION("a face seen edge-on by its uvs") {
    AlongUvFace f = alongUvGroundQuad(0, 2, 2, 0, 2, 0, 2);
    for (auto& uv : f.uvs) uv[1] = 0.5;
    CHECK_FALSE(insertAlongUvFaces({f}, alongUvCube(), kUnitSourceBox, options, out, error));
    CHECK(error.find("no face with uvs of any area") != std::string::npos);
  }
  SECTION("more copies than the limit") {
    options.maxFaces = 100;
    CHECK_FALSE(insertAlongUvFaces({alongUvGroundQuad(0, 10, 2, 0, 0.1, 0, 2)}, alongUvCube(), kUnitSourceBox, options,
                                   out, error));
    CHECK(error.find("more than 100 faces") != std::string::npos);
  }
}

TEST_CASE("insertAlongUV: a deadline that has passed stops the insertion", "[cga][insert_along_uv]") {
  // --max-seconds must reach inside one shape's insertion (the engines turn it into R004).
  AlongUvOptions options;
  options.height = 0.5;
  std::vector<std::vector<Vec3>> out;
  std::string error;
  Deadline open = Deadline::after(3600);
  options.deadline = &open;
  CHECK(insertAlongUvFaces({alongUvGroundQuad(0, 10, 2, 0, 2.5, 0, 2)}, alongUvCube(), kUnitSourceBox, options, out,
                           error));
  Deadline passed(Deadline::Clock::now() - std::chrono::seconds(10), 1.0);
  options.deadline = &passed;
  CHECK_THROWS_AS(insertAlongUvFaces({alongUvGroundQuad(0, 10, 2, 0, 2.5, 0, 2)}, alongUvCube(), kUnitSourceBox,
                                     options, out, error),
                  TimeLimitReached);
}

namespace {

// The 10 x 2 quad of the first case (u = x / 2.5, v = z / 2) as cuts x cuts faces, face
// i cuts + j at column i and row j.
std::vector<AlongUvFace> alongUvCutQuad(int cuts) {
  std::vector<AlongUvFace> faces;
  for (int i = 0; i < cuts; ++i)
    for (int j = 0; j < cuts; ++j) {
      const double u0 = 4.0 * i / cuts, u1 = 4.0 * (i + 1) / cuts, v0 = double(j) / cuts, v1 = double(j + 1) / cuts;
      AlongUvFace f;
      f.uvs = {{u0, v0}, {u0, v1}, {u1, v1}, {u1, v0}};
      for (const auto& uv : f.uvs) f.corners.emplace_back(2.5 * uv[0], 0.0, 2.0 * uv[1]);
      faces.push_back(std::move(f));
    }
  return faces;
}

}  // namespace

TEST_CASE("insertAlongUV: the 10 x 2 quad cut into 300 x 300 faces gives the same boxes", "[cga][insert_along_uv]") {
  // The quad of the first case as 90 000 faces, u = x / 2.5 (i / 75 at column i) and
  // v = z / 2 (j / 300 at row j): the four boxes 2.5 x 0.5 x 2 again, cut along the faces'
  // edges, 10 m3 and 58 m2. The boxes' ends at u = 1, 2, 3 lie on the faces' edges: each
  // goes to one face only (twice would add 1 m2 each). Faces found through the grid over
  // their uvs, not by scanning all 90 000 for each piece.
  constexpr int kCuts = 300;
  std::vector<AlongUvFace> faces = alongUvCutQuad(kCuts);
  AlongUvOptions options;
  options.height = 0.5;
  std::vector<std::vector<Vec3>> out;
  std::string error;
  REQUIRE(insertAlongUvFaces(faces, alongUvCube(), kUnitSourceBox, options, out, error));
  CHECK(std::abs(alongUvVolume(out) - 10.0) <= kAlongUvTol);
  CHECK(std::abs(alongUvArea(out) - 58.0) <= kAlongUvTol);
  // Every corner on a box's face (the walls' pieces have corners at any height).
  alongUvCornersOnGridFaces(out, {0, 2.5, 5, 7.5, 10}, {0, 0.5}, {0, 2});

  SECTION("one more face over the uvs of face 45 150 (column 150, row 150) overlaps it") {
    faces.push_back(faces[150 * kCuts + 150]);
    CHECK_FALSE(insertAlongUvFaces(faces, alongUvCube(), kUnitSourceBox, options, out, error));
    CHECK(error.find("the uvs of faces 45150 and 90000 overlap") != std::string::npos);
  }
}

TEST_CASE("insertAlongUV: vertex normals over the 10 x 2 quad cut into 100 x 100 faces", "[cga][insert_along_uv]") {
  // 40 000 corners merged into 10 201 distinct ones (through buckets, not by comparing each
  // with all before it): all normals are the quad's, so the boxes are those of the first case,
  // 10 m3 and 58 m2, their corners on the boxes' faces.
  AlongUvOptions options;
  options.height = 0.5;
  options.vertexNormals = true;
  std::vector<std::vector<Vec3>> out;
  std::string error;
  REQUIRE(insertAlongUvFaces(alongUvCutQuad(100), alongUvCube(), kUnitSourceBox, options, out, error));
  CHECK(std::abs(alongUvVolume(out) - 10.0) <= kAlongUvTol);
  CHECK(std::abs(alongUvArea(out) - 58.0) <= kAlongUvTol);
  for (const auto& f : out)
    for (const Vec3& p : f) {
      INFO("corner " << p.transpose());
      CHECK((alongUvWithin(p.x(), 0, 10) && alongUvWithin(p.y(), 0, 0.5) && alongUvWithin(p.z(), 0, 2)));
    }
}

TEST_CASE("insertAlongUV: vertex normals merge the corners of many faces along a ridge", "[cga][insert_along_uv]") {
  // A gable 10 m long (z), its slopes at 45 degrees from x -1 (y 0) up to the ridge at x 0
  // (y 1) and down to x 1, each cut into 40 x 50 faces; u = z / 2.5, v = (x + 1) / 2. The
  // ridge's corners are shared by both slopes: their normal is the mean of the slopes',
  // straight up, so the cube's top (h 0.5) crosses the ridge at y 1.5, its highest point.
  // Corners not merged would keep each slope's normal there: y 1 + 0.5 / sqrt 2.
  std::vector<AlongUvFace> faces;
  auto surface = [](double x, double z) { return Vec3(x, 1.0 - std::abs(x), z); };
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 50; ++j) {
        const double z0 = 0.25 * i, z1 = 0.25 * (i + 1), x0 = side - 1 + j / 50.0, x1 = side - 1 + (j + 1) / 50.0;
        AlongUvFace f;
        f.corners = {surface(x0, z0), surface(x0, z1), surface(x1, z1), surface(x1, z0)};
        for (const Vec3& c : f.corners) f.uvs.push_back({c.z() / 2.5, (c.x() + 1.0) / 2.0});
        faces.push_back(std::move(f));
      }
  AlongUvOptions options;
  options.height = 0.5;
  options.vertexNormals = true;
  std::vector<std::vector<Vec3>> out;
  std::string error;
  REQUIRE(insertAlongUvFaces(faces, alongUvCube(), kUnitSourceBox, options, out, error));
  double top = -INFINITY;
  bool ridgeTop = false;
  for (const auto& f : out)
    for (const Vec3& p : f) top = std::max(top, p.y()), ridgeTop = ridgeTop || alongUvNear(p, Vec3(0, 1.5, 2.5));
  CHECK(std::abs(top - 1.5) <= kAlongUvTol);
  CHECK(ridgeTop);
}
