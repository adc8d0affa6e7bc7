#include "runtime/marching/chart_walk.h"

#include "runtime/surface/locate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace fgsg::rt::marching {

namespace {

// Faces a walk or a landing search may visit before giving up: far more than the few
// texels they cover on any sound atlas, few enough to bound a query.
constexpr int kMaxWalkFaces = 1 << 16;
constexpr int kMaxLandingFaces = 256;
// A landing search looks at faces up to this many times the start face's distance.
constexpr double kLandingReach = 1.5;
// Rates of change this small relative to the largest are rounding, not a crossing.
constexpr double kAlongEdge = 1e-10;

}  // namespace

Vec3 tidyBary(const Vec3& bary) {
  const Vec3 b = bary.cwiseMax(0.0);
  const double sum = b.sum();
  return sum > 0 ? Vec3(b / sum) : Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3);
}

FaceExit faceExit(const ImageTriangle& t, const Vec3& bary, const Vec2& d) {
  const Vec3 rate = t.baryRate(d);
  // A line along an edge leaves neither face through it; rounding must not make it
  // leave both in turn (each at length 0, forever).
  const double along = kAlongEdge * rate.cwiseAbs().maxCoeff();
  FaceExit e;
  e.length = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (!(rate[i] < -along)) continue;
    const double length = std::max(0.0, bary[i]) / -rate[i];
    if (e.corner < 0 || length < e.length || (length == e.length && rate[i] < rate[e.corner])) {
      e.length = length;
      e.corner = i;
    }
  }
  if (e.corner >= 0) e.edge = (e.corner + 1) % 3;
  return e;
}

Vec3 baryAcross(const surface::SurfaceMesh& mesh, int f, int edge, const Vec3& bary, int g) {
  const int a = mesh.faces[f][edge], b = mesh.faces[f][(edge + 1) % 3];
  Vec3 out = Vec3::Zero();
  out[mesh.cornerOf(g, a)] = std::max(0.0, bary[edge]);
  out[mesh.cornerOf(g, b)] = std::max(0.0, bary[(edge + 1) % 3]);
  return tidyBary(out);
}

bool walkTo(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles, ChartPoint& p,
            const Vec2& x) {
  for (int visited = 0; visited < kMaxWalkFaces; ++visited) {
    const ImageTriangle& t = triangles[p.face];
    const Vec2 here = t.imagePoint(p.bary);
    const Vec2 offset = x - here;
    const double remaining = offset.norm();
    const Vec3 atX = t.baryOf(x);
    if (remaining == 0 || atX.minCoeff() >= 0) {
      p.bary = tidyBary(atX);
      return true;
    }
    const Vec2 d = offset / remaining;
    const FaceExit e = faceExit(t, p.bary, d);
    if (e.edge < 0) return false;
    if (e.length >= remaining) {  // rounding: x is on this face's border
      p.bary = tidyBary(p.bary + remaining * t.baryRate(d));
      return true;
    }
    Vec3 exitBary = p.bary + e.length * t.baryRate(d);
    exitBary[e.corner] = 0;
    p.bary = tidyBary(exitBary);
    const int g = t.continuation[e.edge];
    if (g < 0) return false;
    p.bary = baryAcross(mesh, p.face, e.edge, p.bary, g);
    p.face = g;
  }
  return false;
}

bool landNear(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles, int start,
              const Vec3& P, double tolerance, ChartPoint& out) {
  struct Candidate {
    int face;
    double distance;
    Vec3 bary;
  };
  auto measure = [&](int f) {
    const auto& v = mesh.faces[f];
    Candidate c{f, 0, Vec3::Zero()};
    const Vec3 q = surface::closestPointOnTriangle(P, mesh.vertices[v[0]], mesh.vertices[v[1]],
                                                   mesh.vertices[v[2]], c.bary);
    c.distance = (q - P).norm();
    return c;
  };
  // Fixed buffers: a landing happens at every jump, from many threads.
  std::array<int, kMaxLandingFaces> visited;
  std::array<Candidate, kMaxLandingFaces> frontier;
  int seen = 1, open = 1;
  visited[0] = start;
  frontier[0] = measure(start);
  Candidate best = frontier[0];
  const double reach = kLandingReach * best.distance + tolerance;
  while (open > 0 && best.distance > tolerance) {
    int nearest = 0;
    for (int i = 1; i < open; ++i)
      if (frontier[i].distance < frontier[nearest].distance) nearest = i;
    const Candidate here = frontier[nearest];
    frontier[nearest] = frontier[--open];
    if (here.distance < best.distance) best = here;
    for (int k = 0; k < 3; ++k) {
      const int g = triangles[here.face].continuation[k];
      if (g < 0 || seen == kMaxLandingFaces || std::find(visited.begin(), visited.begin() + seen, g) != visited.begin() + seen)
        continue;
      visited[seen++] = g;
      const Candidate next = measure(g);
      // Not only faces closer than this one: along a jagged chart border in 3D the way
      // to P can lead a little farther first. Anything within the start's reach (with
      // room) is looked at, nearest first.
      if (next.distance <= reach) frontier[open++] = next;
    }
  }
  out.face = best.face;
  out.bary = tidyBary(best.bary);
  return best.distance <= tolerance;
}

}  // namespace fgsg::rt::marching
