// CityEngine's envelope: the largest solid over a convex polygon that stays below every
// edge's plane (rising inward from the edge's base height at its slope angle) and below
// maxHeight. The top is the lower envelope of those planes: each plane's face is the part
// of the polygon where it is the lowest (a convex polygon, clipped by one half-plane per
// other plane), walls stand on the edges up to where the top meets them.
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"
#include "runtime/planar.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {
namespace {

// h(p) = a p.x + b p.y + c above the polygon's plane.
struct EnvelopePlane {
  double a, b, c;
  double at(const Vec2& p) const { return a * p.x() + b * p.y() + c; }
};

// Sutherland-Hodgman: the part of a convex polygon where g(p) = a x + b y + c <= 0.
std::vector<Vec2> envelopeKeepBelow(const std::vector<Vec2>& poly, const EnvelopePlane& g) {
  std::vector<Vec2> out;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2& s = poly[i];
    const Vec2& e = poly[(i + 1) % n];
    const double gs = g.at(s), ge = g.at(e);
    if (gs <= 0) out.push_back(s);
    if ((gs < 0 && ge > 0) || (gs > 0 && ge < 0)) out.push_back(s + (e - s) * (gs / (gs - ge)));
  }
  return out;
}

std::string envelopeNumber(double v) {
  std::ostringstream m;
  m << v;
  return m.str();
}

}  // namespace

std::vector<EnvelopeEdge> envelopeEdgesBySide(const std::vector<unsigned>& classes, const double* values,
                                              size_t count) {
  // values: front (base, angle), then back, then side or right and left, each a pair.
  std::vector<EnvelopeEdge> out(classes.size());
  const size_t pairs = count / 2;
  auto pairAt = [&](size_t k) { return EnvelopeEdge{values[2 * k], values[2 * k + 1]}; };
  for (size_t i = 0; i < classes.size(); ++i) {
    const unsigned c = classes[i];
    if (c & kEdgeStreetFront) out[i] = pairAt(0);
    else if ((c & kEdgeStreetBack) && pairs > 1) out[i] = pairAt(1);
    else if ((c & kEdgeStreetRight) && pairs > 2) out[i] = pairAt(2);
    else if ((c & kEdgeStreetLeft) && pairs > 2) out[i] = pairAt(pairs > 3 ? 3 : 2);
  }
  return out;
}

bool envelope(const Scope& scope, const GeomRef& geom, const FlatPolygon& polygon, bool worldUp, double maxHeight,
              const std::vector<EnvelopeEdge>& edges, GeometryArena& arena, Part& out, std::string& error) {
  const std::vector<Vec2>& ring = polygon.ring;
  const size_t n = ring.size();
  if (!(maxHeight > 0.0) || !std::isfinite(maxHeight)) {
    error = "envelope: maxHeight " + envelopeNumber(maxHeight) + " must be a number more than 0";
    return false;
  }
  if (n < 3 || edges.size() != n) {
    error = "envelope: expects a polygon with 3 corners at least";
    return false;
  }
  for (size_t i = 0; i < n; ++i) {
    if (!(edges[i].baseHeight >= 0.0) || !std::isfinite(edges[i].baseHeight)) {
      error = "envelope: the base height " + envelopeNumber(edges[i].baseHeight) + " of edge " + std::to_string(i) +
              " must be a number not below 0";
      return false;
    }
    if (!(edges[i].angleDeg >= 0.0 && edges[i].angleDeg <= 90.0)) {
      error = "envelope: the angle " + envelopeNumber(edges[i].angleDeg) + " of edge " + std::to_string(i) +
              " must be between 0 and 90 degrees";
      return false;
    }
  }
  const Vec3 up = Vec3::UnitY();
  if (worldUp && polygon.scope.Z().dot(up) < 1.0 - 1e-9) {
    error = "envelope: world.up needs a face looking up (a horizontal polygon); this one's normal is (" +
            envelopeNumber(polygon.scope.Z().x()) + ", " + envelopeNumber(polygon.scope.Z().y()) + ", " +
            envelopeNumber(polygon.scope.Z().z()) + "): use normal";
    return false;
  }
  double extent = 0.0;
  for (const Vec2& p : ring) extent = std::max(extent, (p - ring[0]).norm());
  const double eps = 1e-9 * extent;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 e0 = ring[i] - ring[(i + n - 1) % n], e1 = ring[(i + 1) % n] - ring[i];
    if (e0.x() * e1.y() - e0.y() * e1.x() < -eps * (e0.norm() + e1.norm())) {
      error = "envelope: the polygon is concave at corner " + std::to_string(i) +
              " (not supported yet: convexify, then comp(f) and an envelope per piece)";
      return false;
    }
  }
  // One plane per sloped edge (90 degrees: a wall to maxHeight, no plane), then the cap.
  std::vector<EnvelopePlane> planes;
  for (size_t i = 0; i < n; ++i) {
    if (edges[i].angleDeg == 90.0) continue;
    const Vec2 t = (ring[(i + 1) % n] - ring[i]).normalized();
    const Vec2 inward(-t.y(), t.x());
    const double k = std::tan(edges[i].angleDeg * M_PI / 180.0);
    planes.push_back({k * inward.x(), k * inward.y(), edges[i].baseHeight - k * inward.dot(ring[i])});
  }
  planes.push_back({0.0, 0.0, maxHeight});
  auto height = [&](const Vec2& p) {
    double h = maxHeight;
    for (const EnvelopePlane& q : planes) h = std::min(h, q.at(p));
    return std::max(h, 0.0);
  };

  // Each plane's face: the polygon where it is the lowest (the first of equal planes).
  std::vector<std::vector<Vec2>> tops;
  for (size_t k = 0; k < planes.size(); ++k) {
    std::vector<Vec2> face = ring;
    for (size_t j = 0; j < planes.size() && face.size() >= 3; ++j) {
      if (j == k) continue;
      const EnvelopePlane g{planes[k].a - planes[j].a, planes[k].b - planes[j].b, planes[k].c - planes[j].c};
      if (std::abs(g.a) * extent + std::abs(g.b) * extent + std::abs(g.c) <= eps * (1.0 + maxHeight)) {
        if (j < k) face.clear();  // the same plane as an earlier one: that one has the face
        continue;
      }
      face = envelopeKeepBelow(face, g);
    }
    if (face.size() >= 3 && twiceRingArea(face) > 1e-12 * extent * extent) tops.push_back(std::move(face));
  }
  // Corners shared by faces and walls welded to one point each (the polygon's corners first).
  std::vector<Vec2> corners = ring;
  auto weld = [&](const Vec2& p) {
    for (const Vec2& c : corners)
      if ((c - p).norm() <= eps) return c;
    corners.push_back(p);
    return p;
  };
  for (auto& face : tops) {
    std::vector<Vec2> welded;
    for (const Vec2& p : face) {
      const Vec2 w = weld(p);
      if (welded.empty() || welded.back() != w) welded.push_back(w);
    }
    while (welded.size() > 1 && welded.front() == welded.back()) welded.pop_back();
    face = std::move(welded);
  }

  const Vec3 erect = worldUp ? up : polygon.scope.Z();
  auto world = [&](const Vec2& p, double h) {
    return Vec3(polygon.scope.P + polygon.scope.X() * p.x() + polygon.scope.Y() * p.y() + erect * h);
  };
  double top = 0.0;
  for (const Vec2& c : corners) top = std::max(top, height(c));
  if (!(top > eps)) {
    error = "envelope: the envelope has no height (every edge's plane starts at 0 and lies flat)";
    return false;
  }
  std::vector<Polygon3> faces;
  // Walls, in edge order: the edge at the bottom, the top's corners on it above.
  for (size_t i = 0; i < n; ++i) {
    const Vec2 p = ring[i], q = ring[(i + 1) % n];
    const Vec2 along = q - p;
    std::vector<std::pair<double, Vec2>> onEdge;
    for (const Vec2& c : corners) {
      const double s = (c - p).dot(along) / along.squaredNorm();
      const Vec2 foot = p + along * s;
      if (s > -1e-12 && s < 1 + 1e-12 && (c - foot).norm() <= eps) onEdge.emplace_back(s, c);
    }
    std::sort(onEdge.begin(), onEdge.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
    Polygon3 wall{world(p, 0.0), world(q, 0.0)};
    bool tall = false;
    for (auto it = onEdge.rbegin(); it != onEdge.rend(); ++it) {
      const double h = height(it->second);
      if (h > eps) wall.push_back(world(it->second, h)), tall = true;
    }
    if (tall) faces.push_back(std::move(wall));
  }
  for (const auto& face : tops) {
    Polygon3 lifted;
    for (const Vec2& p : face) lifted.push_back(world(p, height(p)));
    faces.push_back(std::move(lifted));
  }
  Polygon3 bottom;
  for (size_t i = n; i-- > 0;) bottom.push_back(world(ring[i], 0.0));
  faces.push_back(std::move(bottom));

  // The scope is extrude's to the envelope's height; the faces in its unit coordinates.
  Part prism;
  if (!extrude(scope, geom, top, arena, prism, error)) {
    error = "envelope: " + error;
    return false;
  }
  const Mat3 toUnit = prism.scope.axes.inverse();
  for (Polygon3& face : faces)
    for (Vec3& v : face) v = (toUnit * (v - prism.scope.P)).cwiseQuotient(prism.scope.S);
  out = Part{};
  out.scope = prism.scope;
  out.geom = arena.addPolyhedron(faces);
  return true;
}

}  // namespace fgsg::rt::cga
