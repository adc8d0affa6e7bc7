// Tracing on a triangle mesh (FGSG §4.3): straightest geodesics are straight lines on a
// plane and helices on a cylinder; streamlines keep their angle to the field (lines,
// circles); the reflection heuristic carries a curve through wedges and trisectors; and
// tens of thousands of random traces never leave the surface, never fail, and repeat
// exactly.
#include "runtime/field/trace.h"

#include <catch2/catch.hpp>

#include "runtime/surface/load_surface.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>

using namespace fgsg::rt;
using namespace fgsg::rt::field;

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- meshes -------------------------------------------------------------------------

// nx x ny square cells of side h in the XY plane from the origin, each cut along its
// main diagonal ((i, j)-(i+1, j+1)) or, with `anti`, the other one.
SurfaceMesh grid(int nx, int ny, double h, bool anti = false) {
  SurfaceMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.vertices.push_back(Vec3(i * h, j * h, 0));
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (anti) {
        m.faces.push_back({a, b, d});
        m.faces.push_back({b, c, d});
      } else {
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      }
    }
  m.buildTopology();
  return m;
}

// An open cylinder of radius r about Z from z = -height/2 to height/2: n quads around,
// rows along; outward normals.
SurfaceMesh cylinder(double r, int n, int rows, double height) {
  SurfaceMesh m;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < n; ++i) {
      const double a = 2 * kPi * i / n;
      m.vertices.push_back(Vec3(r * std::cos(a), r * std::sin(a), -height / 2 + height * j / rows));
    }
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * n + i, b = j * n + (i + 1) % n, c = b + n, d = a + n;
      m.faces.push_back({a, b, c});
      m.faces.push_back({a, c, d});
    }
  m.buildTopology();
  return m;
}

// The icosahedron subdivided `levels` times, projected onto the unit sphere.
SurfaceMesh icosphere(int levels) {
  SurfaceMesh m;
  const double t = (1 + std::sqrt(5.0)) / 2;
  for (const Vec3& v : {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0),
                        Vec3(0, -1, t), Vec3(0, 1, t), Vec3(0, -1, -t), Vec3(0, 1, -t),
                        Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)})
    m.vertices.push_back(v.normalized());
  m.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      return mid[key] = int(m.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (auto f : m.faces) {
      const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      next.insert(next.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
    }
    m.faces = std::move(next);
  }
  m.buildTopology();
  return m;
}

// A bumpy torus (major radius 2, minor 0.7) with its vertices jittered along the
// surface: irregular triangles, both signs of curvature, valences 6 everywhere but
// uneven angles.
SurfaceMesh bumpyTorus(int nu, int nv, uint32_t seed) {
  SurfaceMesh m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * kPi * (i + jitter(rng)) / nu, v = 2 * kPi * (j + jitter(rng)) / nv;
      const double r = 0.7 * (1 + 0.15 * std::sin(5 * u) * std::cos(3 * v));
      m.vertices.push_back(Vec3((2 + r * std::cos(v)) * std::cos(u),
                                (2 + r * std::cos(v)) * std::sin(u), r * std::sin(v)));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = j * nu + i, b = j * nu + (i + 1) % nu, c = ((j + 1) % nv) * nu + (i + 1) % nu,
                d = ((j + 1) % nv) * nu + i;
      if ((i + j) % 2) {
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      } else {
        m.faces.push_back({a, b, d});
        m.faces.push_back({b, c, d});
      }
    }
  m.buildTopology();
  return m;
}

// A grid with jittered interior vertices lifted onto a wavy height field: boundary,
// irregular triangles, curvature.
SurfaceMesh wavyPatch(int n, uint32_t seed) {
  SurfaceMesh m = grid(n, n, 1.0 / n, false);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.35 / n, 0.35 / n);
  for (Vec3& v : m.vertices) {
    if (v.x() > 0 && v.x() < 1 && v.y() > 0 && v.y() < 1) v += Vec3(jitter(rng), jitter(rng), 0);
    v.z() = 0.15 * std::sin(6 * v.x()) * std::cos(5 * v.y());
  }
  m.buildTopology();
  return m;
}

// The face of a flat XY mesh holding p, as a surface point (brute force).
SurfacePoint locate(const SurfaceMesh& m, const Vec3& p) {
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const Vec3 &a = m.vertices[m.faces[f][0]], &b = m.vertices[m.faces[f][1]],
               &c = m.vertices[m.faces[f][2]];
    const double area = (b - a).cross(c - a).z();
    const double l0 = (c - b).cross(p - b).z() / area, l1 = (a - c).cross(p - c).z() / area;
    const double l2 = 1 - l0 - l1;
    if (l0 >= 0 && l1 >= 0 && l2 >= 0) return {int(f), Vec3(l0, l1, l2)};
  }
  FAIL("point outside the mesh: " << p.transpose());
  return {};
}

// ---- fields ---------------------------------------------------------------------------

// A field given by a function of position, made tangent at each point; optionally a
// line field whose returned sign flips from face to face (tracing must not care), and
// optionally with degenerate points listed.
class AnalyticField : public DirectionField {
 public:
  AnalyticField(const SurfaceMesh& m, std::function<Vec3(const Vec3&)> f, bool line = false)
      : m_(m), f_(std::move(f)), line_(line) {}

  bool direction(const SurfacePoint& p, Vec3& out) const override {
    const Vec3 n = p.normal(m_);
    Vec3 v = f_(p.position(m_));
    v -= v.dot(n) * n;
    if (!(v.norm() > 1e-9)) return false;
    out = v.normalized();
    if (line_ && p.face % 3 == 1) out = -out;
    return true;
  }
  bool isLineField() const override { return line_; }
  const std::vector<Degeneracy>& degeneraciesIn(int face) const override {
    auto it = degeneracies_.find(face);
    return it == degeneracies_.end() ? none_ : it->second;
  }
  void addDegeneracy(SurfacePoint at, Degeneracy::Kind kind, int indexTimesTwo) {
    Degeneracy d;
    d.face = at.face;
    d.at = at;
    d.kind = kind;
    d.indexTimesTwo = indexTimesTwo;
    degeneracies_[at.face].push_back(d);
  }

 private:
  const SurfaceMesh& m_;
  std::function<Vec3(const Vec3&)> f_;
  bool line_;
  std::map<int, std::vector<Degeneracy>> degeneracies_;
  std::vector<Degeneracy> none_;
};

// ---- checks ---------------------------------------------------------------------------

void checkNear(const Vec3& actual, const Vec3& expected, double margin) {
  INFO("actual (" << actual.transpose() << "), expected (" << expected.transpose() << ")");
  CHECK((actual - expected).norm() <= margin);
}

// What is wrong with a trace result ("" when nothing): a valid surface point with clean
// barycentrics, a unit direction tangent to the smooth normal there, a field direction
// that is zero or unit and tangent, a length within the request (all of it unless
// stopped).
std::string problems(const SurfaceMesh& m, const TraceResult& r, double requested) {
  std::ostringstream out;
  const SurfacePoint& p = r.end;
  if (p.face < 0 || size_t(p.face) >= m.faces.size()) return "end face out of range";
  for (int i = 0; i < 3; ++i)
    if (!(p.bary[i] >= 0 && p.bary[i] <= 1))
      out << "barycentric " << i << " = " << p.bary[i] << "; ";
  if (!(std::abs(p.bary.sum() - 1) <= 1e-12)) out << "barycentrics sum to " << p.bary.sum() << "; ";
  if (!p.position(m).allFinite()) out << "position not finite; ";
  const Vec3 n = p.normal(m);
  if (!(std::abs(r.direction.norm() - 1) <= 1e-9))
    out << "|direction| = " << r.direction.norm() << "; ";
  if (!(std::abs(r.direction.dot(n)) <= 1e-9))
    out << "direction . normal = " << r.direction.dot(n) << "; ";
  const double fn = r.fieldDirection.norm();
  if (!(fn == 0 || (std::abs(fn - 1) <= 1e-9 && std::abs(r.fieldDirection.dot(n)) <= 1e-9)))
    out << "field direction not unit tangent; ";
  if (!(r.length >= 0 && r.length <= requested * (1 + 1e-12) + 1e-12))
    out << "length " << r.length << "; ";
  if (!r.stopped && !(std::abs(r.length - requested) <= 1e-9 * (1 + requested)))
    out << "not stopped but length " << r.length << " of " << requested << "; ";
  if (r.crossings < 0) out << "negative crossings; ";
  return out.str();
}

bool same(const TraceResult& a, const TraceResult& b) {
  return a.end.face == b.end.face && a.end.bary == b.end.bary && a.direction == b.direction &&
         a.fieldDirection == b.fieldDirection && a.length == b.length &&
         a.crossings == b.crossings && a.stopped == b.stopped;
}

// A random point: mostly inside faces, a tenth on edges and a tenth on vertices.
SurfacePoint randomPoint(const SurfaceMesh& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  SurfacePoint p;
  p.face = std::uniform_int_distribution<int>(0, int(m.faces.size()) - 1)(rng);
  const double kind = u(rng);
  const int k = std::uniform_int_distribution<int>(0, 2)(rng);
  if (kind < 0.1) {
    p.bary = Vec3::Zero();
    p.bary[k] = 1;
  } else if (kind < 0.2) {
    const double a = u(rng);
    p.bary = Vec3::Zero();
    p.bary[k] = a;
    p.bary[(k + 1) % 3] = 1 - a;
  } else {
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    p.bary = Vec3(a, b, 1 - a - b);
  }
  return p;
}

Vec3 randomTangent(const SurfaceMesh& m, const SurfacePoint& p, std::mt19937& rng) {
  std::normal_distribution<double> g;
  const Vec3 n = p.normal(m);
  for (;;) {
    Vec3 v(g(rng), g(rng), g(rng));
    v -= v.dot(n) * n;
    if (v.norm() > 1e-3) return v.normalized();
  }
}

// `count` random geodesic traces and as many field traces (a vector field, a line field,
// and the line field with wedges and trisectors listed in every 40th face so that the
// reflection heuristic runs all over, a third of the time each) on m, lengths up to three
// times the mesh's size. Every result is checked; every 7th trace is repeated and must
// come out the same.
void randomTraces(const SurfaceMesh& m, int count, uint32_t seed) {
  std::mt19937 rng(seed);
  const double size = (m.boundsMax - m.boundsMin).norm();
  std::uniform_real_distribution<double> u(0, 1);
  const Vec3 centre = 0.5 * (m.boundsMin + m.boundsMax);
  auto smooth = [centre, size](const Vec3& x) -> Vec3 {
    const Vec3 y = (x - centre) / size;
    return Vec3(-y.y(), y.x(), 0.3 * y.x()) +
           0.4 * Vec3(std::sin(7 * y.y()), std::cos(5 * y.z()), std::sin(6 * y.x()));
  };
  const AnalyticField vectors(m, smooth), lines(m, smooth, true);
  AnalyticField jumpy(m, smooth, true);
  for (size_t f = 0; f < m.faces.size(); f += 40)
    jumpy.addDegeneracy({int(f), Vec3(0.2, 0.3, 0.5)},
                        f % 80 ? Degeneracy::Wedge : Degeneracy::Trisector, f % 80 ? 1 : -1);
  int failures = 0, stopped = 0, repeats = 0;
  long crossings = 0;
  std::string first;
  for (int i = 0; i < 2 * count; ++i) {
    const SurfacePoint start = randomPoint(m, rng);
    const Vec3 dir = randomTangent(m, start, rng);
    const double length = 3 * size * u(rng) * u(rng);
    const double angle = (u(rng) - 0.5) * 2 * kPi;
    const bool geodesic = i < count;
    const DirectionField& field = i % 3 == 0 ? vectors : (i % 3 == 1 ? lines : jumpy);
    auto trace = [&] {
      return geodesic ? traceGeodesic(m, start, dir, length)
                      : traceField(m, field, start, dir, angle, length);
    };
    TraceResult r;
    std::string problem;
    try {
      r = trace();
      problem = problems(m, r, length);
      if (problem.empty() && geodesic && r.fieldDirection != Vec3::Zero())
        problem = "a geodesic has a field direction";
      if (problem.empty() && i % 7 == 0) {
        ++repeats;
        if (!same(r, trace())) problem = "not deterministic";
      }
    } catch (const std::exception& e) {
      problem = std::string("exception: ") + e.what();
    }
    stopped += r.stopped;
    crossings += r.crossings;
    if (!problem.empty() && failures++ == 0) {
      std::ostringstream s;
      s << (geodesic ? "geodesic" : "field") << " trace " << i << " from face " << start.face
        << " bary (" << start.bary.transpose() << ") dir (" << dir.transpose() << ") angle "
        << angle << " length " << length << ": " << problem;
      first = s.str();
    }
  }
  INFO(first);
  INFO(2 * count << " traces, " << stopped << " stopped early, " << crossings << " crossings, "
                 << repeats << " repeated");
  CHECK(failures == 0);
  CHECK(repeats > 0);
  CHECK(crossings > 10L * count);  // they really went places
}

}  // namespace

// ---- angles -----------------------------------------------------------------------------

TEST_CASE("oriented angles and rotations about a normal", "[trace]") {
  const Vec3 z = Vec3::UnitZ();
  CHECK(orientedAngle(Vec3::UnitX(), Vec3::UnitY(), z) == Approx(kPi / 2));
  CHECK(orientedAngle(Vec3::UnitY(), Vec3::UnitX(), z) == Approx(-kPi / 2));
  CHECK(orientedAngle(Vec3::UnitX(), -Vec3::UnitX(), z) == Approx(kPi));  // (-pi, pi]
  CHECK(orientedAngle(Vec3::UnitX(), Vec3(-1, -0.0, 0), z) == Approx(kPi));
  CHECK(orientedAngle(Vec3::UnitX(), Vec3(1, 1, 5), z) == Approx(kPi / 4));  // projected
  CHECK(orientedAngle(Vec3::UnitX(), Vec3::UnitY(), -z) == Approx(-kPi / 2));
  CHECK(orientedAngle(Vec3::Zero(), Vec3::UnitY(), z) == 0);
  checkNear(rotateAbout(Vec3::UnitX(), z, kPi / 2), Vec3::UnitY(), 1e-15);
  checkNear(rotateAbout(Vec3(1, 0, 1), z, kPi), Vec3(-1, 0, 1), 1e-15);
  for (double a : {-3.0, -1.0, 0.0, 0.5, 2.0, 3.1})
    CHECK(orientedAngle(Vec3(1, 2, 0), rotateAbout(Vec3(1, 2, 0), z, a), z) == Approx(a));
}

// ---- geodesics ------------------------------------------------------------------------

TEST_CASE("geodesics on a flat grid are Euclidean translations", "[trace]") {
  for (bool anti : {false, true}) {
    INFO((anti ? "anti-diagonal" : "diagonal") << " cells");
    const double h = 0.1;
    const SurfaceMesh m = grid(20, 20, h, anti);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);

    SECTION("from random points inside faces, on edges and on vertices") {
      for (int i = 0; i < 300; ++i) {
        const SurfacePoint start = randomPoint(m, rng);
        const Vec3 p = start.position(m);
        const double a = 2 * kPi * u(rng);
        const Vec3 d(std::cos(a), std::sin(a), 0);
        // Stay clear of the boundary: the distance to it along d, less a margin.
        double room = 1e30;
        for (int k = 0; k < 2; ++k) {
          if (d[k] > 1e-9) room = std::min(room, (2 - p[k]) / d[k]);
          if (d[k] < -1e-9) room = std::min(room, -p[k] / d[k]);
        }
        const double length = 0.95 * room * u(rng);
        const TraceResult r = traceGeodesic(m, start, d, length);
        INFO("trace " << i << " from (" << p.transpose() << ") at " << a << " for " << length);
        CHECK(problems(m, r, length).empty());
        CHECK_FALSE(r.stopped);
        CHECK(r.length == Approx(length).margin(1e-12));
        checkNear(r.end.position(m), p + length * d, 1e-9);
        checkNear(r.direction, d, 1e-9);
        CHECK(r.fieldDirection == Vec3::Zero());
      }
    }
    SECTION("through vertices along the diagonal and along grid lines") {
      const Vec3 s = Vec3(8, 9, 0) * h;
      for (Vec3 d : {Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(1, 2, 0)}) {
        d.normalize();
        const SurfacePoint start = locate(m, s);
        REQUIRE((start.bary.array() == 0).count() == 2);  // a vertex
        const double length = 0.7;
        const TraceResult r = traceGeodesic(m, start, d, length);
        INFO("direction (" << d.transpose() << ")");
        CHECK(problems(m, r, length).empty());
        CHECK_FALSE(r.stopped);
        checkNear(r.end.position(m), s + length * d, 1e-9);
        checkNear(r.direction, d, 1e-9);
        CHECK(r.crossings >= 3);
      }
    }
    SECTION("from the middle of an edge, into the face the direction points into") {
      // The cell's diagonal edge: between corners 1 and 2 of (a, b, d), 0 and 2 of (a, b, c).
      const SurfacePoint start{2 * (5 * 20 + 5), anti ? Vec3(0, 0.4, 0.6) : Vec3(0.4, 0, 0.6)};
      const Vec3 p = start.position(m);
      for (double a : {0.1, 1.0, 2.0, 3.0, -0.5, -2.0, kPi / 4, -3 * kPi / 4}) {
        const Vec3 d(std::cos(a), std::sin(a), 0);
        const TraceResult r = traceGeodesic(m, start, d, 0.05);
        CHECK(problems(m, r, 0.05).empty());
        checkNear(r.end.position(m), p + 0.05 * d, 1e-9);
      }
    }
    SECTION("stops at the boundary") {
      const SurfacePoint start = locate(m, Vec3(1.03, 0.77, 0));
      const Vec3 d = Vec3(1, 0.5, 0).normalized();
      const TraceResult r = traceGeodesic(m, start, d, 5);
      CHECK(r.stopped);
      CHECK(problems(m, r, 5).empty());
      CHECK(r.length == Approx((2 - 1.03) / d.x()).epsilon(1e-12));
      checkNear(r.end.position(m), Vec3(1.03, 0.77, 0) + r.length * d, 1e-9);
      // Pointing out of the grid at a boundary vertex: no move at all.
      const TraceResult out = traceGeodesic(m, locate(m, Vec3(0, 0, 0)), Vec3(-1, -1, 0), 1);
      CHECK(out.stopped);
      CHECK(out.length == 0);
    }
  }
}

TEST_CASE("geodesics on a cylinder are helices", "[trace]") {
  const double r = 1, height = 12;
  const int n = 256;
  const SurfaceMesh m = cylinder(r, n, 120, height);
  // Start inside a face half way up, and on a vertex.
  const int row = 60;
  const SurfacePoint inside{2 * (row * n + 10), Vec3(0.5, 0.3, 0.2)};
  const SurfacePoint vertex{2 * (row * n + 40), Vec3(1, 0, 0)};
  for (const SurfacePoint& start : {inside, vertex}) {
    const Vec3 p = start.position(m);
    const double a = std::atan2(p.y(), p.x());
    const Vec3 axis = Vec3::UnitZ(), around(-std::sin(a), std::cos(a), 0);
    for (double alpha : {0.0, 0.3, 0.8, 1.2, 1.5, kPi / 2, 2.5}) {
      const double length = 5;
      const Vec3 dir = std::cos(alpha) * axis + std::sin(alpha) * around;
      const TraceResult t = traceGeodesic(m, start, dir, length);
      INFO("alpha " << alpha << " from (" << p.transpose() << ")");
      CHECK(problems(m, t, length).empty());
      CHECK_FALSE(t.stopped);
      const Vec3 e = t.end.position(m);
      // The unrolled straight line: axial advance L cos(alpha), angle L sin(alpha) / r.
      // The prism's facets unroll exactly, so the axial advance is exact; its girth is
      // (1 - 2.5e-5) of the circle's, which the angle sees.
      CHECK(e.z() - p.z() == Approx(length * std::cos(alpha)).margin(1e-9));
      const double turned =
          std::remainder(std::atan2(e.y(), e.x()) - a - length * std::sin(alpha) / r, 2 * kPi);
      CHECK(std::abs(turned) < 1e-3);
      const double b = a + length * std::sin(alpha) / r;
      const Vec3 helix(r * std::cos(b), r * std::sin(b), p.z() + length * std::cos(alpha));
      CHECK((e - helix).norm() < 0.01 * r);
      CHECK(t.direction.z() == Approx(std::cos(alpha)).margin(1e-9));
    }
  }
}

TEST_CASE("straightest geodesics on a sphere close up after a great circle", "[trace]") {
  const SurfaceMesh m = icosphere(5);
  std::mt19937 rng(3);
  for (int i = 0; i < 20; ++i) {
    const SurfacePoint start = randomPoint(m, rng);
    const Vec3 dir = randomTangent(m, start, rng);
    const TraceResult r = traceGeodesic(m, start, dir, 2 * kPi);
    CHECK(problems(m, r, 2 * kPi).empty());
    // The polyhedral sphere's great circles are not closed exactly; a few edge lengths.
    CHECK((r.end.position(m) - start.position(m)).norm() < 0.1);
    // A quarter of the way round, it is 90 degrees from the start on the sphere.
    const TraceResult q = traceGeodesic(m, start, dir, kPi / 2);
    CHECK(std::abs(q.end.position(m).normalized().dot(start.position(m).normalized())) < 0.03);
  }
}

// ---- field traces ---------------------------------------------------------------------

TEST_CASE("streamlines on a flat grid: constant fields, circles and rays", "[trace]") {
  const double h = 0.05;
  const SurfaceMesh m = grid(80, 80, h, true);  // 4 x 4
  const Vec3 c(2.013, 1.971, 0);                // field centre, inside a face

  SECTION("a constant field at angle a: the straight line at angle a to it") {
    const AnalyticField f(m, [](const Vec3&) { return Vec3(1, 0, 0); });
    const Vec3 s(2.02, 2.31, 0);
    for (double a : {0.0, 0.3, kPi / 2, -2.0, kPi}) {
      const Vec3 d(std::cos(a), std::sin(a), 0);
      const TraceResult r = traceField(m, f, locate(m, s), Vec3(0, 1, 0), a, 1.5);
      INFO("angle " << a);
      CHECK(problems(m, r, 1.5).empty());
      CHECK_FALSE(r.stopped);
      checkNear(r.end.position(m), s + 1.5 * d, 1e-9);
      checkNear(r.direction, d, 1e-9);
      checkNear(r.fieldDirection, Vec3(1, 0, 0), 1e-12);
    }
  }
  SECTION("a constant line field: the sign goes the way the caller asks") {
    const AnalyticField f(
        m, [](const Vec3&) { return Vec3(1, 0, 0); }, true);
    const Vec3 s(2.02, 1.31, 0);
    for (double a : {0.0, 0.4, 2.0}) {
      for (const Vec3& want : {Vec3(-1, 0.2, 0), Vec3(1, -0.3, 0), Vec3(0.3, 1, 0)}) {
        const Vec3 plus(std::cos(a), std::sin(a), 0);
        const Vec3 d = plus.dot(want) >= 0 ? plus : Vec3(-plus);
        const TraceResult r = traceField(m, f, locate(m, s), want, a, 1.2);
        INFO("angle " << a << " wanted (" << want.transpose() << ")");
        CHECK(problems(m, r, 1.2).empty());
        checkNear(r.end.position(m), s + 1.2 * d, 1e-9);
        checkNear(r.direction, d, 1e-9);
        // The field direction reported is the sign the trace used.
        CHECK(orientedAngle(r.fieldDirection, r.direction, Vec3::UnitZ()) == Approx(a));
      }
    }
  }
  SECTION("a centre field: circles that close after a full turn") {
    auto centre = [c](const Vec3& x) { return Vec3(-(x.y() - c.y()), x.x() - c.x(), 0); };
    const AnalyticField vectors(m, centre), lines(m, centre, true);
    for (const DirectionField* f :
         {(const DirectionField*)&vectors, (const DirectionField*)&lines}) {
      for (double radius : {0.4, 1.5}) {
        const Vec3 s = c + Vec3(radius, 0, 0);
        const TraceResult quarter =
            traceField(m, *f, locate(m, s), Vec3(0, 1, 0), 0, kPi * radius / 2);
        INFO((f == &vectors ? "vector" : "line") << " field, radius " << radius);
        checkNear(quarter.end.position(m), c + Vec3(0, radius, 0), 1e-4 * radius);
        const TraceResult r = traceField(m, *f, locate(m, s), Vec3(0, 1, 0), 0, 2 * kPi * radius);
        CHECK(problems(m, r, 2 * kPi * radius).empty());
        CHECK_FALSE(r.stopped);
        checkNear(r.end.position(m), s, 1e-4 * radius);
        checkNear(r.direction, Vec3(0, 1, 0), 1e-4);
        CHECK(r.crossings > 2 * kPi * radius / h);
      }
    }
  }
  SECTION("a radial field: rays at angle 0, circles at a right angle") {
    auto radial = [c](const Vec3& x) { return Vec3(x.x() - c.x(), x.y() - c.y(), 0); };
    const AnalyticField f(m, radial);
    const Vec3 s = c + 0.5 * Vec3(std::cos(0.7), std::sin(0.7), 0);
    const TraceResult ray = traceField(m, f, locate(m, s), Vec3::Zero(), 0, 1.0);
    checkNear(ray.end.position(m), c + 1.5 * Vec3(std::cos(0.7), std::sin(0.7), 0), 1e-9);
    const TraceResult circle = traceField(m, f, locate(m, s), Vec3::Zero(), kPi / 2, kPi * 0.5);
    checkNear(circle.end.position(m), c - (s - c), 1e-5);  // half way round
    // Through the centre, where the field vanishes: the trace stops there.
    const TraceResult in = traceField(m, f, locate(m, s), Vec3::Zero(), kPi, 1.0);
    CHECK(in.stopped);
    CHECK(in.length == Approx(0.5).margin(0.03));
  }
}

TEST_CASE("streamlines pass through wedges and trisectors", "[trace]") {
  const double h = 0.05;
  const SurfaceMesh m = grid(40, 40, h, true);  // 2 x 2
  const Vec3 d(1.013, 0.971, 0);                // the degenerate point, inside a face
  const SurfacePoint at = locate(m, d);
  REQUIRE((at.bary.array() > 0.01).all());
  // Line fields with a +1/2 (wedge) and a -1/2 (trisector) singularity at d: the major
  // direction turns by +-half the polar angle.
  auto wedge = [d](const Vec3& x) {
    const double phi = std::atan2(x.y() - d.y(), x.x() - d.x());
    return Vec3(std::cos(phi / 2), std::sin(phi / 2), 0);
  };
  auto trisector = [d](const Vec3& x) {
    const double phi = std::atan2(x.y() - d.y(), x.x() - d.x());
    return Vec3(std::cos(-phi / 2), std::sin(-phi / 2), 0);
  };
  struct Case {
    const char* name;
    std::function<Vec3(const Vec3&)> f;
    Degeneracy::Kind kind;
    int index;
  };
  for (const Case& k : {Case{"wedge", wedge, Degeneracy::Wedge, 1},
                        Case{"trisector", trisector, Degeneracy::Trisector, -1}}) {
    AnalyticField field(m, k.f, true);
    const AnalyticField unmarked(m, k.f, true);  // the same field, singularity not listed
    field.addDegeneracy(at, k.kind, k.index);
    for (double offset : {0.0005, -0.0003, 0.0}) {
      // Coming in along the direction that runs into d (the field is radial on the +x
      // axis for both), slightly off it, heading -x: close enough to reach the jump
      // radius (a trisector deflects curves at offset y from r^1.5 ~ y r^0.5 away).
      const Vec3 s = d + Vec3(0.4, offset, 0);
      const double length = 0.9;
      INFO(k.name << ", offset " << offset);
      const TraceResult r = traceField(m, field, locate(m, s), Vec3(-1, 0, 0), 0, length);
      CHECK(problems(m, r, length).empty());
      CHECK_FALSE(r.stopped);
      const Vec3 e = r.end.position(m);
      INFO("ended at (" << e.transpose() << "), heading (" << r.direction.transpose() << ")");
      CHECK(e.x() < d.x() - 0.4);            // well past the singularity
      CHECK(std::abs(e.y() - d.y()) < 0.1);  // roughly straight on
      CHECK(r.direction.x() < -0.9);         // still going away from it
      if (offset != 0) {
        // Without the heuristic the curve cannot get through: a wedge turns it back, a
        // trisector sends it off sideways (or it stops at d).
        const TraceResult plain = traceField(m, unmarked, locate(m, s), Vec3(-1, 0, 0), 0, length);
        const Vec3 pe = plain.end.position(m);
        INFO("without: ended at (" << pe.transpose() << "), heading ("
                                   << plain.direction.transpose() << ")");
        CHECK_FALSE(
            (pe.x() < d.x() - 0.4 && std::abs(pe.y() - d.y()) < 0.1 && plain.direction.x() < -0.9));
      }
    }
  }
}

// ---- random traces --------------------------------------------------------------------

TEST_CASE("20000 random traces on procedural meshes stay on the surface", "[trace]") {
  SECTION("icosphere (2562 vertices)") { randomTraces(icosphere(4), 20000, 11); }
  SECTION("bumpy jittered torus (9600 vertices)") {
    randomTraces(bumpyTorus(120, 80, 5), 20000, 12);
  }
  SECTION("wavy patch with a boundary (3721 vertices)") {
    randomTraces(wavyPatch(60, 9), 20000, 13);
  }
  SECTION("open cylinder (7680 vertices)") { randomTraces(cylinder(0.5, 96, 79, 3), 20000, 14); }
}

TEST_CASE("20000 random traces on each real mesh stay on the surface", "[trace][realmesh]") {
  // tests/data/meshes is filled by scripts/fetch-test-meshes.sh (see tests/data/README.md).
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(FGSG_SOURCE_DIR) / "tests" / "data" / "meshes";
  uint32_t seed = 17;
  for (const char* name :
       {"bunny00.off", "armadillo.off", "elephant.off", "ChineseDragon-10kv.off"}) {
    const fs::path path = dir / name;
    if (!fs::exists(path))
      FAIL("tests/data/meshes/" << name << " is missing: run scripts/fetch-test-meshes.sh");
    SurfaceMesh mesh;
    std::string error;
    INFO(name);
    REQUIRE(surface::loadSurface(path.string(), mesh, error));
    randomTraces(mesh, 20000, seed++);
  }
}
