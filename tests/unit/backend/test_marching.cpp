// The Marching and Branch commands and texture contexts as grammars use them (Buron et
// al. 2015): straight marches on a flat surface, conditions read at the destination,
// painted masks, branches, seeds, smooth terminals and the errors.
#include "derive_helpers.h"
#include "../runtime/scratch_files.h"
#include "runtime/marching/curve_frame.h"
#include "runtime/marching/marching_surface.h"
#include "runtime/surface/procedural.h"
#include "runtime/texture/paint_mask.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg;
using fgsg::test::deriveText;
using fgsg::test::unitPoint;

namespace {

// The instances of `asset`, in output order.
std::vector<const rt::Instance*> instancesOf(const rt::DeriveResult& r, const std::string& asset) {
  std::vector<const rt::Instance*> out;
  for (const auto& inst : r.instances.instances)
    if (r.instances.assets[inst.asset] == asset) out.push_back(&inst);
  return out;
}

rt::DeriveOptions inFolder(const std::filesystem::path& dir) {
  rt::DeriveOptions o;
  o.assetDirs.push_back(dir.string());
  return o;
}

}  // namespace

TEST_CASE("Marching on a flat surface walks straight steps of exactly its length", "[marching]") {
  auto r = deriveText(R"(
    surface plane(4, 4, 32);
    start = Walk(0)
    Walk(n) : n < 12 ~> Marching(0.1, 0, true){ Mark Walk(n + 1) }
    Mark ~> I("cube")
  )");
  REQUIRE(r.ok);
  const auto marks = instancesOf(r, "cube");
  REQUIRE(marks.size() == 12);
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();  // the start: the plane's centre
  for (size_t k = 0; k < marks.size(); ++k) {
    const Eigen::Vector3d p = unitPoint(*marks[k], 0, 0, 0);
    CHECK((p - previous).norm() == Approx(0.1).margin(1e-9));
    CHECK(p.x() == Approx(0.1 * (k + 1)).margin(1e-9));  // along the start's X: world X
    CHECK(p.y() == Approx(0.0).margin(1e-9));
    CHECK(p.z() == Approx(0.0).margin(1e-12));
    previous = p;
  }
}

TEST_CASE("Marching turns by its angle counter-clockwise about the normal, like RS", "[marching]") {
  auto r = deriveText(R"(
    surface plane(4, 4, 32);
    start = Marching(0.5, 90, true){ I("cube") }
  )");
  REQUIRE(r.ok);
  const auto marks = instancesOf(r, "cube");
  REQUIRE(marks.size() == 1);
  const Eigen::Vector3d p = unitPoint(*marks[0], 0, 0, 0);
  CHECK(p.x() == Approx(0.0).margin(1e-9));
  CHECK(p.y() == Approx(0.5).margin(1e-9));
}

TEST_CASE("Extruded spans the segment and its terminals get the segment's smooth curve", "[marching]") {
  auto r = deriveText(R"(
    surface plane(4, 4, 32);
    start = S(1, 0.02, 0.02) Walk(0)
    Walk(n) : n < 5 ~> Marching(0.2, 10, true){ Walk(n + 1), I("cube") }
  )");
  REQUIRE(r.ok);
  const auto pieces = instancesOf(r, "cube");
  REQUIRE(pieces.size() == 5);
  REQUIRE(r.instances.curves.size() == 5);
  for (size_t k = 0; k < pieces.size(); ++k) {
    const rt::Instance& inst = *pieces[k];
    REQUIRE(inst.curve < r.instances.curves.size());
    const rt::CurveSegment& c = r.instances.curves[inst.curve];
    const Eigen::Vector3d a(c.control[0][0], c.control[0][1], c.control[0][2]);
    const Eigen::Vector3d b(c.control[3][0], c.control[3][1], c.control[3][2]);
    CHECK((b - a).norm() == Approx(0.2).margin(1e-9));
    // The scope's X runs along the segment, as long as it; the segment is the middle
    // line of the scope's bottom face.
    CHECK((unitPoint(inst, 1, 0.5, 0) - unitPoint(inst, 0, 0.5, 0) - (b - a)).norm() < 1e-9);
    CHECK((unitPoint(inst, 0, 0.5, 0) - a).norm() < 1e-9);
  }
  // Consecutive curves share their joint, with one derivative there (C1).
  for (size_t k = 0; k + 1 < r.instances.curves.size(); ++k) {
    const auto& c0 = r.instances.curves[pieces[k]->curve];
    const auto& c1 = r.instances.curves[pieces[k + 1]->curve];
    for (int i = 0; i < 3; ++i) {
      CHECK(c0.control[3][i] == Approx(c1.control[0][i]).margin(1e-12));
      CHECK(c0.control[3][i] - c0.control[2][i] == Approx(c1.control[1][i] - c1.control[0][i]).margin(1e-9));
    }
  }
}

TEST_CASE("A failed condition tries the half circle ahead and stops when nothing holds", "[marching]") {
  // Only destinations with y <= 0.25 are allowed, heading +Y: straight ahead fails after
  // two steps, then the sideways candidates carry on along the line y <= 0.25.
  auto r = deriveText(R"(
    surface plane(4, 4, 32);
    start = RS(90) Walk(0)
    Walk(n) : n < 8 ~> Marching(0.1, 0, Scope.py <= 0.25){ I("cube") Walk(n + 1) }
  )");
  REQUIRE(r.ok);
  const auto marks = instancesOf(r, "cube");
  REQUIRE(marks.size() == 8);
  for (const auto* m : marks) CHECK(unitPoint(*m, 0, 0, 0).y() <= 0.25 + 1e-12);
  CHECK(unitPoint(*marks[1], 0, 0, 0).y() == Approx(0.2).margin(1e-9));

  rt::DeriveOptions straightOnly;
  straightOnly.marchCandidates = 0;
  auto stopped = deriveText(R"(
    surface plane(4, 4, 32);
    start = RS(90) Walk(0)
    Walk(n) : n < 8 ~> Marching(0.1, 0, Scope.py <= 0.25){ I("cube") Walk(n + 1) }
  )", straightOnly);
  REQUIRE(stopped.ok);
  CHECK(instancesOf(stopped, "cube").size() == 2);
}

TEST_CASE("A painted mask keeps the march inside the painted area", "[marching][texture]") {
  const auto dir = test::scratchDir("marching", "mask");
  // Paint the disc of radius 0.6 around (0.5, 0, 0) on the very surface the grammar uses.
  rt::surface::SurfaceMesh plane;
  std::string error;
  REQUIRE(rt::surface::makeProceduralSurface("plane", {4, 4, 32}, plane, error));
  const auto surface = rt::marching::MarchingSurface::prepare(plane, {}, error);
  REQUIRE(surface);
  const auto mask = rt::texture::paintMask(*surface, 512, {{rt::Vec3(0.5, 0, 0), 0.6}});
  REQUIRE(rt::texture::writeMaskPng(mask, (dir / "disc.png").string(), error));
  auto r = deriveText(R"(
    surface plane(4, 4, 32);
    texture disc = "disc.png";
    start = Walk(0)
    Walk(n) : n < 40 ~> Marching(0.05, Rand(-30, 30), context.disc(texCoord) > 0.5){ I("cube") Walk(n + 1) }
  )", inFolder(dir));
  REQUIRE(r.ok);
  const auto marks = instancesOf(r, "cube");
  CHECK(marks.size() == 40);
  const double pixel = 4.0 * std::sqrt(2.0) / 512;  // the atlas spreads 4 x 4 over at most 512 pixels
  for (const auto* m : marks) CHECK((unitPoint(*m, 0, 0, 0) - rt::Vec3(0.5, 0, 0)).norm() <= 0.6 + 2 * pixel);
}

TEST_CASE("Branch(n) derives its first part n-1 times and its last part once", "[marching]") {
  auto r = deriveText(R"(
    surface plane(4, 4, 8);
    start = Branch(4){ I("cube"), I("sphere") } Branch(2){ I("torus") }
  )");
  REQUIRE(r.ok);
  CHECK(test::countAsset(r, "cube") == 3);
  CHECK(test::countAsset(r, "sphere") == 1);
  CHECK(test::countAsset(r, "torus") == 2);
}

TEST_CASE("Each seed grows with its own random stream", "[marching]") {
  const std::string grammar = R"(
    surface sphere(1);
    start = Walk(0)
    Walk(n) : n < 6 ~> Marching(0.1, Rand(-40, 40), true){ I("cube") Walk(n + 1) }
  )";
  rt::DeriveOptions one, two;
  one.seeds.resize(1);
  one.seeds[0].point[2] = 1;
  two.seeds = one.seeds;
  two.seeds.resize(2);
  two.seeds[1].point[0] = 1;
  auto a = deriveText(grammar, one), b = deriveText(grammar, two);
  REQUIRE(a.ok);
  REQUIRE(b.ok);
  REQUIRE(a.instances.instances.size() == 6 + 1);  // and the surface
  REQUIRE(b.instances.instances.size() == 12 + 1);
  // The first seed's plant is the same alone or with another: its stream is its own.
  std::vector<Eigen::Vector3d> alone, together;
  for (const auto* m : instancesOf(a, "cube")) alone.push_back(unitPoint(*m, 0, 0, 0));
  for (const auto* m : instancesOf(b, "cube"))
    if (unitPoint(*m, 0, 0, 0).z() > 0.3) together.push_back(unitPoint(*m, 0, 0, 0));
  REQUIRE(alone.size() == together.size());
  for (const auto& p : alone) {
    bool found = false;
    for (const auto& q : together) found |= (p - q).norm() < 1e-12;
    CHECK(found);
  }
  for (const auto& p : alone) CHECK(p.norm() == Approx(1.0).margin(0.02));  // on the sphere
}

TEST_CASE("Marching and texture errors are located and name the problem", "[marching][errors]") {
  auto plane = deriveText("start = Marching(0.1, 0, true){ I(\"cube\") }");
  REQUIRE(plane.messages.size() == 1);
  CHECK(plane.messages[0].code == "R022");

  auto negative = deriveText("surface plane(2, 2);\nstart = Marching(-0.1, 0, true){ I(\"cube\") }");
  REQUIRE(negative.messages.size() == 1);
  CHECK(negative.messages[0].code == "R024");
  CHECK(negative.messages[0].line == 2);
  CHECK(negative.messages[0].col == 9);

  auto branches = deriveText("surface plane(2, 2);\nstart = Branch(2.5){ I(\"cube\") }");
  REQUIRE(branches.messages.size() == 1);
  CHECK(branches.messages[0].code == "R024");

  const auto dir = test::scratchDir("marching", "missing");
  auto missing = deriveText("surface plane(2, 2);\ntexture paint = \"nowhere.png\";\nstart = I(\"cube\")", inFolder(dir));
  REQUIRE(missing.messages.size() == 1);
  CHECK(missing.messages[0].code == "R023");
  CHECK(missing.messages[0].line == 2);
  CHECK(missing.messages[0].message.find("nowhere.png") != std::string::npos);
}

TEST_CASE("Seeds drawn by density from a texture sprout only where it is painted", "[marching][texture]") {
  const auto dir = test::scratchDir("marching", "density");
  rt::surface::SurfaceMesh plane;
  std::string error;
  REQUIRE(rt::surface::makeProceduralSurface("plane", {4, 4, 32}, plane, error));
  const auto surface = rt::marching::MarchingSurface::prepare(plane, {}, error);
  REQUIRE(surface);
  const auto mask = rt::texture::paintMask(*surface, 512, {{rt::Vec3(-1, 1, 0), 0.5}});
  REQUIRE(rt::texture::writeMaskPng(mask, (dir / "spot.png").string(), error));
  rt::DeriveOptions opt = inFolder(dir);
  opt.seedDensity = "spot";
  opt.seedCount = 50;
  const std::string grammar = "surface plane(4, 4, 32);\ntexture spot = \"spot.png\";\nstart = I(\"cube\")";
  auto r = deriveText(grammar, opt);
  REQUIRE(r.ok);
  const auto seeds = instancesOf(r, "cube");
  REQUIRE(seeds.size() == 50);
  const double pixel = 4.0 * std::sqrt(2.0) / 512;
  for (const auto* s : seeds) CHECK((unitPoint(*s, 0, 0, 0) - rt::Vec3(-1, 1, 0)).norm() <= 0.5 + 2 * pixel);
  // The same run seed draws the same seeds.
  auto again = deriveText(grammar, opt);
  REQUIRE(again.instances.instances.size() == r.instances.instances.size());
  for (size_t k = 0; k < seeds.size(); ++k)
    CHECK(again.instances.instances[k].transform == r.instances.instances[k].transform);

  opt.seedDensity = "nothing";
  auto unknown = deriveText(grammar, opt);
  REQUIRE(unknown.messages.size() == 1);
  CHECK(unknown.messages[0].code == "R023");
}

TEST_CASE("A step longer than the surface is wide stops the march at once", "[marching]") {
  auto r = deriveText(R"(
    surface sphere(1);
    start = Marching(2.5, 0, true){ I("cube") } Marching(1.9, 0, true){ I("sphere") }
  )");
  REQUIRE(r.ok);
  CHECK(test::countAsset(r, "cube") == 0);    // no two points of the unit sphere are 2.5 apart
  CHECK(test::countAsset(r, "sphere") == 1);  // 1.9 is a chord of it
}

TEST_CASE("Seeds without a surface are an error, not ignored", "[marching][errors]") {
  rt::DeriveOptions opt;
  opt.seeds.resize(1);
  auto r = deriveText("start = I(\"cube\")", opt);
  REQUIRE(r.messages.size() == 1);
  CHECK(r.messages[0].code == "R022");
  CHECK_FALSE(r.ok);
}

TEST_CASE("A march that can never start is a warning that says why", "[marching][errors]") {
  // #46: seeds all outside the painted disc: every march's condition fails wherever it
  // lands, nothing grows — R030 at the Marching, naming the reason, with the count.
  const auto dir = test::scratchDir("marching", "never");
  rt::surface::SurfaceMesh plane;
  std::string error;
  REQUIRE(rt::surface::makeProceduralSurface("plane", {4, 4, 32}, plane, error));
  const auto surface = rt::marching::MarchingSurface::prepare(plane, {}, error);
  REQUIRE(surface);
  const auto mask = rt::texture::paintMask(*surface, 512, {{rt::Vec3(0.5, 0, 0), 0.3}});
  REQUIRE(rt::texture::writeMaskPng(mask, (dir / "disc.png").string(), error));
  rt::DeriveOptions opt = inFolder(dir);
  opt.seeds.resize(2);
  opt.seeds[0].point[0] = -1.5, opt.seeds[0].point[1] = -1.5;
  opt.seeds[1].point[0] = 1.5, opt.seeds[1].point[1] = 1.5;
  auto r = deriveText("surface plane(4, 4, 32);\ntexture disc = \"disc.png\";\n"
                      "start = Walk(0)\n"
                      "Walk(n) : n < 40 ~> Marching(0.05, 0, context.disc(texCoord) > 0.5){ I(\"cube\") Walk(n + 1) }",
                      opt);
  REQUIRE(r.ok);
  CHECK(test::countAsset(r, "cube") == 0);
  REQUIRE(r.messages.size() == 1);
  CHECK_FALSE(r.messages[0].isError);
  CHECK(r.messages[0].code == "R030");
  CHECK(r.messages[0].line == 4);
  CHECK(r.messages[0].col == 21);
  CHECK_THAT(r.messages[0].message,
             Catch::Contains("no march ever started: all 2 Marching steps stopped where they began") &&
                 Catch::Contains("the condition was false at every destination tried, straight ahead and 8 other "
                                 "directions (--march-candidates)") &&
                 Catch::Contains("texture says no (2 marches)"));

  // Longer than the unit sphere's bounding-box diagonal (2 sqrt 3 = 3.46), and longer than
  // any chord (2.5 > 2) though not than the diagonal: those reasons instead.
  auto tooLong = deriveText("surface sphere(1);\nstart = Marching(3.5, 0, true){ I(\"cube\") }");
  REQUIRE(tooLong.ok);
  REQUIRE(tooLong.messages.size() == 1);
  CHECK(tooLong.messages[0].code == "R030");
  CHECK_THAT(tooLong.messages[0].message,
             Catch::Contains("all 1 Marching steps") &&
                 Catch::EndsWith("the step is longer than the surface's bounding-box diagonal (a smaller length, "
                                 "or --surface-size to scale the surface up) (1 march)"));
  auto noChord = deriveText("surface sphere(1);\nstart = Marching(2.5, 0, true){ I(\"cube\") }");
  REQUIRE(noChord.messages.size() == 1);
  CHECK_THAT(noChord.messages[0].message,
             Catch::EndsWith(": no point of the surface lay a step away in any direction tried (its open edge came "
                             "first, or it does not reach that far that way) (1 march)"));

  // One march that moves silences it.
  auto moved = deriveText("surface sphere(1);\nstart = Marching(2.5, 0, true){ I(\"cube\") } "
                          "Marching(0.5, 0, true){ I(\"cube\") }");
  REQUIRE(moved.ok);
  CHECK(moved.messages.empty());
}

// Marching's fourth argument on a flat plane (normal +Z): three steps of 0.2, each turned
// 30° from the last, so step k (from 0) heads (cos 30(k+1)°, sin 30(k+1)°, 0) from march
// point p_k to p_k+1 (p_0 the plane's centre, the origin).
namespace {

struct SmoothnessWalk {
  rt::DeriveResult r;
  std::vector<Eigen::Vector3d> points;       // p_0 .. p_3
  std::vector<const rt::Instance*> pieces;   // the terminals on the three segments
};

SmoothnessWalk walkWithSmoothness(const std::string& smoothness) {
  SmoothnessWalk w;
  w.r = deriveText(R"(
    surface plane(4, 4, 32);
    start = S(1, 0.02, 0.02) Walk(0)
    Walk(n) : n < 3 ~> Marching(0.2, 30, true)" + smoothness + R"(){ Mark Walk(n + 1), I("cube") }
    Mark ~> I("sphere")
  )");
  REQUIRE(w.r.ok);
  w.points.push_back(Eigen::Vector3d::Zero());
  for (const rt::Instance* mark : instancesOf(w.r, "sphere")) w.points.push_back(unitPoint(*mark, 0, 0, 0));
  w.pieces = instancesOf(w.r, "cube");
  REQUIRE(w.points.size() == 4);
  REQUIRE(w.pieces.size() == 3);
  return w;
}

Eigen::Vector3d smoothnessHeading(int step) {
  const double a = 30.0 * (step + 1) * M_PI / 180.0;
  return {std::cos(a), std::sin(a), 0};
}

Eigen::Vector3d smoothnessCurvePoint(const rt::CurveSegment& c, double x) { return rt::marching::bezierPoint(c, x); }
Eigen::Vector3d smoothnessCurveDerivative(const rt::CurveSegment& c, double x) { return rt::marching::bezierDerivative(c, x); }
double smoothnessAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

TEST_CASE("Marching with smoothness none leaves rigid pieces along the chords", "[marching][smoothness]") {
  const SmoothnessWalk w = walkWithSmoothness(R"(, "none")");
  for (int k = 0; k < 3; ++k) {
    INFO("step " << k);
    CHECK((w.points[size_t(k) + 1] - w.points[size_t(k)] - 0.2 * smoothnessHeading(k)).norm() < 1e-9);
    const rt::Instance& piece = *w.pieces[size_t(k)];
    CHECK(piece.curve == UINT32_MAX);  // not bent
    CHECK((unitPoint(piece, 0, 0.5, 0) - w.points[size_t(k)]).norm() < 1e-9);
    CHECK((unitPoint(piece, 1, 0.5, 0) - w.points[size_t(k) + 1]).norm() < 1e-9);
    CHECK(((unitPoint(piece, 1, 0.5, 0) - unitPoint(piece, 0, 0.5, 0)).normalized() - smoothnessHeading(k)).norm() < 1e-9);
  }
}

TEST_CASE("Marching with smoothness C0 bends pieces along curves that meet but kink", "[marching][smoothness]") {
  const SmoothnessWalk w = walkWithSmoothness(R"(, "C0")");
  for (int k = 0; k < 3; ++k) {
    INFO("step " << k);
    const rt::Instance& piece = *w.pieces[size_t(k)];
    REQUIRE(piece.curve < w.r.instances.curves.size());
    const rt::CurveSegment& c = w.r.instances.curves[piece.curve];
    CHECK((smoothnessCurvePoint(c, 0) - w.points[size_t(k)]).norm() < 1e-9);
    CHECK((smoothnessCurvePoint(c, 1) - w.points[size_t(k) + 1]).norm() < 1e-9);
    // Both end tangents are the chord's direction.
    CHECK((smoothnessCurveDerivative(c, 0).normalized() - smoothnessHeading(k)).norm() < 1e-9);
    CHECK((smoothnessCurveDerivative(c, 1).normalized() - smoothnessHeading(k)).norm() < 1e-9);
    if (k == 0) continue;
    const rt::CurveSegment& before = w.r.instances.curves[w.pieces[size_t(k) - 1]->curve];
    CHECK((smoothnessCurvePoint(before, 1) - smoothnessCurvePoint(c, 0)).norm() < 1e-9);  // no gap at the joint
    CHECK(smoothnessAngle(smoothnessCurveDerivative(before, 1), smoothnessCurveDerivative(c, 0)) == Approx(M_PI / 6).margin(1e-9));
  }
}

TEST_CASE("Marching with smoothness C1, the default, shares the tangent at every joint", "[marching][smoothness]") {
  for (const char* smoothness : {"", R"(, "C1")"}) {
    const SmoothnessWalk w = walkWithSmoothness(smoothness);
    for (int k = 1; k < 3; ++k) {
      INFO("joint " << k << " with '" << smoothness << "'");
      const rt::CurveSegment& before = w.r.instances.curves[w.pieces[size_t(k) - 1]->curve];
      const rt::CurveSegment& c = w.r.instances.curves[w.pieces[size_t(k)]->curve];
      CHECK((smoothnessCurvePoint(before, 1) - smoothnessCurvePoint(c, 0)).norm() < 1e-9);
      CHECK(smoothnessAngle(smoothnessCurveDerivative(before, 1), smoothnessCurveDerivative(c, 0)) == Approx(0).margin(1e-9));
      // The tangent there bisects the two headings.
      CHECK((smoothnessCurveDerivative(c, 0).normalized() - (smoothnessHeading(k - 1) + smoothnessHeading(k)).normalized()).norm() < 1e-9);
    }
  }
}
