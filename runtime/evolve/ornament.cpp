#include "runtime/evolve/ornament.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fgsg::rt::evolve {

namespace {

// A point within this of a border line is on it (as tiles.cpp validates loci).
constexpr double kBorderTolerance = 1e-9;
constexpr int kMaxSamples = 4096;

Point2 operator+(Point2 a, Point2 b) { return {a.x + b.x, a.y + b.y}; }
Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
Point2 operator*(double s, Point2 a) { return {s * a.x, s * a.y}; }
double dot(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }
double length(Point2 a) { return std::hypot(a.x, a.y); }

// The right-hand normal of a direction: C' x n with n = +z, i.e. (y, -x).
Point2 rightNormal(Point2 d) { return {d.y, -d.x}; }

Point2 unit(Point2 d) {
  const double len = length(d);
  return len > 0 ? (1 / len) * d : Point2{0, 0};
}

// The unit direction of segment i of a polyline, or of the nearest segment of non-zero
// length (walking away from i, forwards first), or (0,0) when all points coincide.
Point2 segmentDirection(const std::vector<Point2>& p, size_t i) {
  const size_t m = p.size() - 1;
  for (size_t k = 0; k < m; ++k) {
    for (const size_t s : {i + k, i >= k ? i - k : m}) {
      if (s >= m) continue;
      const Point2 d = unit(p[s + 1] - p[s]);
      if (d.x != 0 || d.y != 0) return d;
    }
  }
  return {0, 0};
}

// The unit tangent of a curve at t: the analytic derivative of a cubic (a central
// difference where it vanishes), a polyline's segment direction, or at a polyline's
// interior vertex the bisector of its two segments' directions.
Point2 unitTangent(const Curve& c, double t) {
  if (c.kind == Curve::Kind::kCubic) {
    const auto& p = c.points;
    const double s = 1 - t;
    const Point2 d = (3 * s * s) * (p[1] - p[0]) + (6 * s * t) * (p[2] - p[1]) + (3 * t * t) * (p[3] - p[2]);
    if (length(d) > 1e-12) return unit(d);
    const double h = 1e-6;
    return unit(c.at(std::min(1.0, t + h)) - c.at(std::max(0.0, t - h)));
  }
  const size_t m = c.points.size() - 1;
  const double u = t * double(m);
  const double k = std::round(u);
  if (std::abs(u - k) < 1e-9 && k > 0 && k < double(m)) {
    const size_t v = size_t(k);
    const Point2 b = unit(segmentDirection(c.points, v - 1) + segmentDirection(c.points, v));
    if (b.x != 0 || b.y != 0) return b;
    return segmentDirection(c.points, v);  // a full reversal: no bisector
  }
  return segmentDirection(c.points, std::min(m - 1, size_t(std::max(0.0, u))));
}

// Parameters in [0,1]: `count` evenly spaced, plus a polyline's vertex parameters i/m;
// ascending, without near-duplicates, 0 and 1 exact.
std::vector<double> parameters(const Curve& c, int count) {
  std::vector<double> ps;
  for (int i = 0; i < count; ++i) ps.push_back(double(i) / double(count - 1));
  if (c.kind == Curve::Kind::kPolyline) {
    const size_t m = c.points.size() - 1;
    for (size_t i = 1; i < m; ++i) ps.push_back(double(i) / double(m));
  }
  std::sort(ps.begin(), ps.end());
  std::vector<double> out;
  for (const double p : ps)
    if (out.empty() || p - out.back() > 1e-9) out.push_back(p);
  out.front() = 0;
  out.back() = 1;
  return out;
}

struct End {
  Point2 point;      // the end point, snapped onto its border line
  Point2 direction;  // the offset direction there: along the border, or the normal
};

// The end point `p` with unit normal `normal`: on one border line (not a corner), the
// point moves exactly onto the line and the offset runs along the line, on the normal's
// side; otherwise both stay.
End endOf(Point2 p, Point2 normal) {
  const bool left = std::abs(p.x) <= kBorderTolerance, right = std::abs(p.x - 1) <= kBorderTolerance;
  const bool bottom = std::abs(p.y) <= kBorderTolerance, top = std::abs(p.y - 1) <= kBorderTolerance;
  const bool vertical = left || right, horizontal = bottom || top;
  if (vertical == horizontal) return {p, normal};  // interior, or a corner
  Point2 e = vertical ? Point2{0, 1} : Point2{1, 0};
  if (dot(e, normal) < 0) e = -1 * e;
  if (vertical) p.x = left ? 0.0 : 1.0;
  else p.y = bottom ? 0.0 : 1.0;
  return {p, e};
}

void checkOptions(const OrnamentOptions& o) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("ornament: " + what); };
  if (!std::isfinite(o.halfWidth) || !(o.halfWidth > 0)) fail("halfWidth must be finite and > 0");
  if (!std::isfinite(o.height) || !(o.height >= 0)) fail("height must be finite and >= 0");
  if (o.samplesAlong < 2 || o.samplesAlong > kMaxSamples) fail("samplesAlong must be in 2..4096");
  if (o.samplesAcross < 2 || o.samplesAcross > kMaxSamples) fail("samplesAcross must be in 2..4096");
}

// A polyline locus's interior vertex: its parameter, the miter factor 1 / cos(a/2) for a
// turn by a (capped at kMaxMiter), and how far along the locus to either side the inner
// rail of the mitred offset runs backwards, d tan(a/2) (capped alike).
struct Corner {
  double t = 0, miter = 1, reach = 0;
};
constexpr double kMaxMiter = 4;

std::vector<Corner> corners(const Curve& locus, double d) {
  std::vector<Corner> out;
  if (locus.kind != Curve::Kind::kPolyline) return out;
  const size_t m = locus.points.size() - 1;
  for (size_t v = 1; v < m; ++v) {
    const Point2 in = rightNormal(segmentDirection(locus.points, v - 1));
    const Point2 mid = unit(in + rightNormal(segmentDirection(locus.points, v)));
    const double c = std::max(dot(mid, in), 1 / kMaxMiter);
    out.push_back({double(v) / double(m), 1 / c, d * std::sqrt(std::max(0.0, 1 - c * c)) / c});
  }
  return out;
}

// Leaves out the samples of a polyline locus (not its vertices) closer to a corner, along
// the locus, than the corner's reach: there the inner rail would run backwards and the
// ornament fold over itself.
void dropNearCorners(const Curve& locus, const std::vector<Corner>& cs, std::vector<double>& ts) {
  if (cs.empty()) return;
  const size_t m = locus.points.size() - 1;
  std::vector<double> kept;
  for (const double t : ts) {
    bool keep = true;
    for (const Corner& c : cs) {
      if (t == c.t) break;  // the vertex itself
      const size_t segment = t < c.t ? size_t(std::lround(c.t * double(m))) - 1 : size_t(std::lround(c.t * double(m)));
      const double along = std::abs(t - c.t) * double(m) *
                           length(locus.points[segment + 1] - locus.points[segment]);
      if (along < c.reach) keep = false;
    }
    if (keep || t == 0 || t == 1) kept.push_back(t);
  }
  ts = std::move(kept);
}

}  // namespace

OrnamentGrid ornamentGrid(const Curve& locus, const Curve& section, const OrnamentOptions& options) {
  checkOptions(options);
  const double d = options.halfWidth;
  OrnamentGrid g;
  const std::vector<Corner> cs = corners(locus, d);
  g.t = parameters(locus, options.samplesAlong);
  dropNearCorners(locus, cs, g.t);
  g.r = parameters(section, options.samplesAcross);

  // Across: x_s + h10 + h11 (the section's x with the Hermite terms) and y_s, per r.
  std::vector<double> across(g.r.size()), up(g.r.size());
  for (size_t j = 0; j < g.r.size(); ++j) {
    const double r = g.r[j];
    Point2 s = section.at(r);
    if (j == 0) s = {-1, 0};  // the section's ends, exactly (validated to 1e-9)
    if (j + 1 == g.r.size()) s = {1, 0};
    const double h10 = r * (r - 1) * (r - 1), h11 = r * r * (r - 1);
    across[j] = d * (s.x + h10 + h11);
    up[j] = options.height * s.y;
  }

  const Point2 n0 = rightNormal(unitTangent(locus, 0)), n1 = rightNormal(unitTangent(locus, 1));
  const End e0 = endOf(locus.start(), n0), e1 = endOf(locus.end(), n1);
  const Point2 fix0 = e0.direction - n0, fix1 = e1.direction - n1;

  g.points.reserve(g.t.size() * g.r.size());
  for (size_t i = 0; i < g.t.size(); ++i) {
    const double t = g.t[i];
    Point2 c, w;
    if (i == 0) {
      c = e0.point, w = e0.direction;
    } else if (i + 1 == g.t.size()) {
      c = e1.point, w = e1.direction;
    } else {
      c = locus.at(t);
      const Point2 blended = rightNormal(unitTangent(locus, t)) + (1 - t) * fix0 + t * fix1;
      if (!(length(blended) > 1e-9))
        throw std::invalid_argument("ornament: the offset direction vanishes at locus parameter " + std::to_string(t));
      w = unit(blended);
      // At a polyline's corner the rails are mitred, so they are the segments' offsets.
      for (const Corner& corner : cs)
        if (corner.t == t) w = corner.miter * w;
    }
    for (size_t j = 0; j < g.r.size(); ++j)
      g.points.push_back({c.x + across[j] * w.x, c.y + across[j] * w.y, up[j]});
  }
  return g;
}

OrnamentGrid ornamentGrid(const TileSet& tiles, Allele allele, const OrnamentOptions& options) {
  const Tile& tile = tiles.tiles.at(allele.symbol);
  Curve locus = tiles.loci.at(size_t(tile.locus)).curve;
  // Turning is affine, so turning the control points turns the curve.
  for (Point2& p : locus.points) p = turnInTile(p, allele.turns);
  return ornamentGrid(locus, tiles.sections.at(size_t(tile.section)).curve, options);
}

rt::Mesh ornamentMesh(const OrnamentGrid& g) {
  rt::Mesh mesh;
  const size_t nt = g.t.size(), nr = g.r.size();
  mesh.positions.resize(3 * nt * nr);
  mesh.texcoords.resize(2 * nt * nr);
  for (size_t i = 0; i < nt; ++i)
    for (size_t j = 0; j < nr; ++j) {
      const size_t v = i * nr + j;
      for (int k = 0; k < 3; ++k) mesh.positions[3 * v + size_t(k)] = float(g.at(i, j)[size_t(k)]);
      mesh.texcoords[2 * v] = float(g.r[j]);
      mesh.texcoords[2 * v + 1] = float(g.t[i]);
    }
  // Per cell, with a = (i, j): a -> a + dr -> a + dt is counter-clockwise from +z, since
  // d/dr runs along W, the right-hand normal, and W x C' points up.
  mesh.indices.resize(6 * (nt - 1) * (nr - 1));
  size_t k = 0;
  for (size_t i = 0; i + 1 < nt; ++i)
    for (size_t j = 0; j + 1 < nr; ++j) {
      const auto a = uint32_t(i * nr + j), b = uint32_t(a + 1), c = uint32_t(a + nr), dd = uint32_t(c + 1);
      for (const uint32_t v : {a, b, c, b, dd, c}) mesh.indices[k++] = v;
    }
  mesh.computeNormals();
  return mesh;
}

rt::Mesh tileOrnament(const TileSet& tiles, Allele allele, const OrnamentOptions& options) {
  return ornamentMesh(ornamentGrid(tiles, allele, options));
}

}  // namespace fgsg::rt::evolve
