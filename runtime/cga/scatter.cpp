// CityEngine's scatter: the points' domains and distributions (runtime/cga/scatter.h).
#include "runtime/cga/scatter.h"

#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

namespace fgsg::rt::cga {
namespace {

std::string scatterNumberText(double v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// Calls visit(local polygon) for each face of the shape's own geometry, in the scope's
// frame (metres from P): a box's six faces, the one face of a flat box (looking along the
// positive axis it has no size in), a polygon's face, a polyhedron's faces.
template <class Visit>
void forEachScatterFace(const Scope& scope, const GeomRef& geom, const GeometryArena& arena, Visit&& visit) {
  Polygon3 local;
  auto emit = [&](const Vec3* pts, std::size_t count) {
    local.clear();
    for (std::size_t i = 0; i < count; ++i) local.push_back(scope.S.cwiseProduct(pts[i]));
    visit(local);
  };
  if (geom.kind == GeomKind::Box) {
    int flatAxis = -1, flats = 0;
    for (int a = 0; a < 3; ++a)
      if (!(scope.S[a] > 0.0)) flatAxis = a, ++flats;
    if (flats > 1) return;  // a line or a point: no surface
    for (const Polygon3& f : unitBoxFaces()) {
      if (flatAxis >= 0 && !(newellNormal(f)[flatAxis] > 0)) continue;
      emit(f.data(), f.size());
    }
  } else if (geom.kind == GeomKind::Polygon) {
    emit(arena.polygon(geom), geom.count);
  } else if (geom.kind == GeomKind::Polyhedron) {
    for (uint32_t i = 0; i < geom.count; ++i) {
      const GeometryArena::Face& f = arena.face(geom, i);
      emit(arena.facePoints(f), f.count);
    }
  }
}

// Whether every edge of the faces is run once each way by faces (a closed, consistently
// oriented surface). Corners are compared on a grid of 1e-9 of the solid's extent.
bool scatterFacesClosed(const std::vector<Polygon3>& faces) {
  double extent = 1.0;
  for (const Polygon3& f : faces)
    for (const Vec3& p : f) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  const double grid = extent * 1e-9;
  using Corner = std::array<long long, 3>;
  auto corner = [&](const Vec3& p) {
    return Corner{std::llround(p.x() / grid), std::llround(p.y() / grid), std::llround(p.z() / grid)};
  };
  std::map<std::pair<Corner, Corner>, int> edges;  // directed edge -> runs minus runs the other way
  for (const Polygon3& f : faces)
    for (std::size_t i = 0; i < f.size(); ++i) {
      const Corner a = corner(f[i]), b = corner(f[(i + 1) % f.size()]);
      if (a == b) continue;
      if (a < b) ++edges[{a, b}];
      else --edges[{b, a}];
    }
  if (edges.empty()) return false;
  for (const auto& [edge, balance] : edges)
    if (balance != 0) return false;
  return true;
}

// The point of triangle abc closest to the origin (Ericson, Real-Time Collision
// Detection 5.1.5, with the query point at the origin).
Vec3 scatterClosestToOrigin(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = -a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = -b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = -c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// The standard normal distribution function.
double scatterPhi(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// The standard normal restricted to [a, b], at quantile u: its distribution function
// inverted by bisection (one uniform number per draw, the same in every engine).
double scatterTruncatedNormal(double u, double a, double b) {
  const bool flip = a > 0;  // work in the lower tail, where the distribution function is exact
  if (flip) std::swap(a, b), a = -a, b = -b;
  a = std::max(a, -38.0), b = std::min(b, 38.0);  // past 38 standard deviations: no mass in doubles
  const double pa = scatterPhi(a), pb = scatterPhi(b);
  const double target = pa + u * (pb - pa);
  double lo = a, hi = b;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (scatterPhi(mid) < target ? lo : hi) = mid;
  }
  const double x = 0.5 * (lo + hi);
  return flip ? -x : x;
}

// Solid angle of triangle abc seen from the origin (Van Oosterom and Strackee).
double scatterSolidAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double num = a.dot(b.cross(c));
  const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(num, den);
}

}  // namespace

bool ScatterSampler::prepare(const Scope& scope, const GeomRef& geom, const GeometryArena& arena,
                             const ScatterSpec& spec, std::string& error) {
  scope_ = scope;
  spec_ = spec;
  triangles_.clear();
  cumulativeArea_.clear();
  if (spec.gaussian && !(std::isfinite(spec.stddev) && spec.stddev > 0)) {
    error = "Scatter: the standard deviation must be a positive number, not " + scatterNumberText(spec.stddev);
    return false;
  }
  static const double kMeans[7][3] = {{0.5, 0.5, 0.5}, {0.5, 0.5, 1}, {0.5, 0.5, 0}, {0, 0.5, 0.5},
                                      {1, 0.5, 0.5},   {0.5, 1, 0.5}, {0.5, 0, 0.5}};
  const double* m = kMeans[static_cast<int>(spec.mean)];
  for (int k = 0; k < 3; ++k) {
    const double size = std::abs(scope.S[k]);
    mean_[k] = m[k] * scope.S[k];
    sigma_[k] = spec.relative ? spec.stddev * size : spec.stddev;
  }

  std::vector<Polygon3> faces;
  forEachScatterFace(scope, geom, arena, [&](const Polygon3& f) { faces.push_back(f); });
  domain_ = spec.domain;
  solidIsBox_ = false;
  if (domain_ == ScatterDomain::Volume) {
    if (geom.kind == GeomKind::Box && scope.S.minCoeff() > 0) {
      solidIsBox_ = true;
    } else if (geom.kind != GeomKind::Polyhedron || !scatterFacesClosed(faces)) {
      domain_ = ScatterDomain::Surface;  // CityEngine: volume needs a closed surface
    }
  }
  if (domain_ == ScatterDomain::Scope || solidIsBox_) {
    lo_ = scope.S.cwiseMin(Vec3::Zero());
    hi_ = scope.S.cwiseMax(Vec3::Zero());
    return true;
  }
  // The faces as triangles (the surface's, or the solid's boundary).
  std::vector<uint32_t> tris;
  bool first = true;
  for (const Polygon3& f : faces) {
    Polygon3 world;
    for (const Vec3& p : f) world.push_back(scope.toWorld(p));
    const Vec3 n = newellNormal(world);
    if (!(n.norm() > 0)) continue;
    tris.clear();
    earClip(f, tris);
    for (std::size_t t = 0; t + 2 < tris.size(); t += 3) {
      Triangle tri{{f[tris[t]], f[tris[t + 1]], f[tris[t + 2]]}, n.normalized()};
      const double area = 0.5 * (tri.local[1] - tri.local[0]).cross(tri.local[2] - tri.local[0]).norm();
      if (!(area > 0)) continue;
      triangles_.push_back(tri);
      cumulativeArea_.push_back((cumulativeArea_.empty() ? 0.0 : cumulativeArea_.back()) + area);
      for (const Vec3& p : tri.local) {
        lo_ = first ? p : Vec3(lo_.cwiseMin(p));
        hi_ = first ? p : Vec3(hi_.cwiseMax(p));
        first = false;
      }
    }
  }
  if (domain_ == ScatterDomain::Surface && spec.gaussian && !triangles_.empty()) {
    // The least exponent on the surface: rejection then accepts there with probability 1.
    closestExponent_ = INFINITY;
    auto standard = [&](const Vec3& p) {
      Vec3 d;
      for (int k = 0; k < 3; ++k) d[k] = sigma_[k] > 0 ? (p[k] - mean_[k]) / sigma_[k] : 0.0;
      return d;
    };
    for (const Triangle& t : triangles_) {
      const Vec3 c = scatterClosestToOrigin(standard(t.local[0]), standard(t.local[1]), standard(t.local[2]));
      closestExponent_ = std::min(closestExponent_, 0.5 * c.squaredNorm());
    }
  }
  return true;
}

double ScatterSampler::drawAxis(RandomStream& rng, int axis, double lo, double hi) const {
  const double u = rng.next();
  if (!(hi > lo)) return lo;
  double x;
  if (!spec_.gaussian) {
    x = lo + u * (hi - lo);
  } else if (!(sigma_[axis] > 0)) {
    x = mean_[axis];
  } else {
    const double s = sigma_[axis];
    x = mean_[axis] + s * scatterTruncatedNormal(u, (lo - mean_[axis]) / s, (hi - mean_[axis]) / s);
  }
  return std::clamp(x, lo, hi);
}

bool ScatterSampler::insideSolid(const Vec3& local) const {
  double angle = 0;
  for (const Triangle& t : triangles_)
    angle += scatterSolidAngle(t.local[0] - local, t.local[1] - local, t.local[2] - local);
  return std::abs(angle) > 2 * M_PI;  // winding number 1 inside, 0 outside
}

double ScatterSampler::gaussianExponent(const Vec3& local) const {
  double e = 0;
  for (int k = 0; k < 3; ++k)
    if (sigma_[k] > 0) e += 0.5 * ((local[k] - mean_[k]) / sigma_[k]) * ((local[k] - mean_[k]) / sigma_[k]);
  return e;
}

Scope ScatterSampler::pointScope(const Vec3& local, const Vec3* normal) const {
  Scope s = scope_;
  s.P = scope_.toWorld(local);
  s.S = Vec3::Zero();
  if (normal) {
    // y along the face's normal, x the parent's x laid onto the face (its z where x stands
    // upright on it), z completing a right-handed frame.
    const Vec3 y = *normal;
    Vec3 x = scope_.X() - scope_.X().dot(y) * y;
    if (x.norm() < 1e-6) x = scope_.Z() - scope_.Z().dot(y) * y;
    x.normalize();
    s.axes.col(0) = x;
    s.axes.col(1) = y;
    s.axes.col(2) = x.cross(y);
  }
  return s;
}

bool ScatterSampler::next(RandomStream& rng, Scope& point, std::string& error, Deadline* deadline) {
  if (domain_ == ScatterDomain::Scope || solidIsBox_) {
    Vec3 local;
    for (int k = 0; k < 3; ++k) local[k] = drawAxis(rng, k, lo_[k], hi_[k]);
    point = pointScope(local, nullptr);
    return true;
  }
  if (empty()) {
    error = "Scatter: the shape has no surface to put points on";
    return false;
  }
  for (uint32_t draw = 0; draw < kMaxDraws; ++draw) {
    if (deadline) deadline->check();  // a decrement; the clock now and then
    if (domain_ == ScatterDomain::Volume) {
      Vec3 local;
      for (int k = 0; k < 3; ++k) local[k] = drawAxis(rng, k, lo_[k], hi_[k]);
      if (insideSolid(local)) {
        point = pointScope(local, nullptr);
        return true;
      }
      continue;
    }
    // A triangle by area, then a uniform point in it (the corner square folded back).
    const double total = cumulativeArea_.back();
    const auto it = std::upper_bound(cumulativeArea_.begin(), cumulativeArea_.end(), rng.next() * total);
    const Triangle& t = triangles_[std::min<std::size_t>(it - cumulativeArea_.begin(), triangles_.size() - 1)];
    double r1 = rng.next(), r2 = rng.next();
    if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
    const Vec3 local = t.local[0] + r1 * (t.local[1] - t.local[0]) + r2 * (t.local[2] - t.local[0]);
    if (spec_.gaussian && !(rng.next() < std::exp(closestExponent_ - gaussianExponent(local)))) continue;
    point = pointScope(local, &t.normal);
    return true;
  }
  error = std::string("Scatter: no point found in ") + std::to_string(kMaxDraws) + " draws: " +
          (domain_ == ScatterDomain::Volume ? "the solid fills almost none of its box"
                                            : "the gaussian's deviation is too small for this surface");
  return false;
}

}  // namespace fgsg::rt::cga
