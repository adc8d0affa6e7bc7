// The mesh walk under both kinds of trace (trace.h): a point moving through one face at a
// time in barycentric coordinates, crossing edges exactly (the shared edge's two
// coordinates carried over, the direction unfolded about the edge) and walking vertex
// fans without allocating. Internal to runtime/field/trace*.cpp.
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <cmath>
#include <limits>

namespace fgsg::rt::field::trace_detail {

using surface::SurfaceMesh;
using surface::SurfacePoint;

// A barycentric coordinate at or below this is zero: the point is on that edge (two: on a
// vertex). Far above what a walk rounds to (1e-16 a step, 1e-13 after thousands of
// crossings), so a curve meant to pass through a vertex does; far below what a caller
// can see (1e-12 of a triangle's height).
constexpr double kSnap = 1e-12;
// A direction within this angle (radians) of an edge runs along it rather than across:
// rounding must not send a curve that slides along an edge over it and back.
constexpr double kParallel = 1e-12;
// Slack when placing a direction in a vertex fan (radians, or the sine of the angle):
// corner-angle sums round to 1e-15; anything past this is really outside.
constexpr double kFanSlack = 1e-9;
// A face no higher than this fraction of its longest edge has no plane to walk in (the
// loader rejects such faces; the walk treats one that slips through as a wall).
constexpr double kDegenerateFace = 1e-10;
// Every trace ends after at most kIterBase + kIterPerHeight * length / h steps, h the
// smallest face height met: crossing a face takes at least one step per height in the
// worst case (a sliver crossed the short way), a field trace a few more per face.
constexpr double kIterBase = 4096;
constexpr double kIterPerHeight = 64;

// One face, ready to walk in.
struct Face {
  int f = -1;
  Vec3 v[3];          // corners
  Vec3 vn[3];         // the corners' vertex normals
  Vec3 n;             // unit normal
  Vec3 g[3];          // gradients of the barycentric coordinates (in the face plane)
  double g2[3] = {};  // |g[i]|^2, 1 / the height over the edge opposite corner i squared
  double scale = 0;   // sqrt(2 area): the leg of a right isosceles triangle of this area
  double height = 0;  // the smallest height
  bool degenerate = true;

  void load(const SurfaceMesh& m, int face);
  // How the barycentric coordinates change per unit of movement along d.
  Vec3 rate(const Vec3& d) const { return {d.dot(g[0]), d.dot(g[1]), d.dot(g[2])}; }
  Vec3 at(const Vec3& b) const { return b[0] * v[0] + b[1] * v[1] + b[2] * v[2]; }
  // The smooth normal at b, as SurfacePoint::normal computes it.
  Vec3 smoothNormal(const Vec3& b) const {
    const Vec3 s = b[0] * vn[0] + b[1] * vn[1] + b[2] * vn[2];
    return s / std::sqrt(s.squaredNorm());
  }
  // Moving at `rate` (of coordinate i, unit speed) leaves through the edge opposite i,
  // rather than running along it.
  bool leaves(double rate, int i) const {
    return rate < 0 && rate * rate > kParallel * kParallel * g2[i];
  }
};

// Rounding cleaned: coordinates at or below kSnap (and NaN) become 0, the rest sum to 1.
inline Vec3 cleanBary(Vec3 b) {
  for (int i = 0; i < 3; ++i)
    if (!(b[i] > kSnap)) b[i] = 0;
  const double sum = b[0] + b[1] + b[2];
  if (!(sum > 0) || !std::isfinite(sum)) return Vec3::Constant(1.0 / 3);
  return b / sum;
}
inline int zeroCount(const Vec3& b) { return (b[0] == 0) + (b[1] == 0) + (b[2] == 0); }
inline int largest(const Vec3& b) {
  return b[0] >= b[1] ? (b[0] >= b[2] ? 0 : 2) : (b[1] >= b[2] ? 1 : 2);
}

// The minimal rotation taking unit `from` to unit `to`, applied to u (a half-turn about an
// axis orthogonal to `from` when they are opposite).
inline Vec3 carry(const Vec3& u, const Vec3& from, const Vec3& to) {
  // The rotation about from x to by their angle: u - ((a+b).u / (1+c)) (a+b) + 2 (a.u) b.
  const double c = from.dot(to);
  if (c > -1 + 1e-12) {
    const Vec3 s = from + to;
    return u - (s.dot(u) / (1 + c)) * s + (2 * from.dot(u)) * to;
  }
  // Opposite normals (a mesh folded onto itself): half a turn about an axis in the plane.
  const Vec3 axis =
      from.cross(std::abs(from.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
  return 2 * axis.dot(u) * axis - u;
}
// The unit part of d orthogonal to unit n; false when there is none to speak of.
bool tangentPart(const Vec3& d, const Vec3& n, Vec3& out);

// The first moment the coordinates b reach an edge moving at `rate`: t (infinity when
// never) and the coordinate that reaches zero. Directions along an edge do not leave.
struct Exit {
  double t;
  int i;
};
inline Exit exitOf(const Face& face, const Vec3& b, const Vec3& rate) {
  Exit e{std::numeric_limits<double>::infinity(), -1};
  for (int i = 0; i < 3; ++i)
    if (face.leaves(rate[i], i)) {
      const double t = b[i] / -rate[i];
      if (t < e.t) e = {t, i};
    }
  return e;
}

// Carries the point b (on the edge opposite corner i of `face`, b[i] == 0) and the unit
// direction dir into the face across that edge, dir unfolded about the edge. False at
// the boundary or towards a degenerate face (nothing changes then).
bool crossEdge(const SurfaceMesh& m, Face& face, Vec3& b, Vec3& dir, int i);
// The same into `to`, already loaded: the face across the edge opposite corner i of `from`.
bool carryAcross(const SurfaceMesh& m, const Face& from, const Face& to, int i, Vec3& b, Vec3& dir);

// The straightest continuation through the vertex at corner k of `face` of a curve that
// arrived there moving along dir (Polthier & Schmies): the angle on either side is half
// the vertex's angle sum; at a boundary vertex, straight on (pi) on whichever side has
// room. Moves face, b and dir to the face it leaves into; false when it would leave the
// surface.
bool straightestThroughVertex(const SurfaceMesh& m, Face& face, Vec3& b, Vec3& dir, int k);

// The face around vertex v (one of whose faces is f) that unit tangent t (in the plane of
// normal nv) points into, and t in that face's plane, clamped into its corner when the
// fan's angles do not add up to the plane's. False when t points off the surface past a
// boundary edge.
bool enterFan(const SurfaceMesh& m, int v, int f, const Vec3& t, const Vec3& nv, int& outFace,
              Vec3& outDir);

// Places a walk starting at (face, b) (b clean) in tangent direction t (unit, in the plane
// of the smooth normal ns there): on a vertex or an edge, in the face t points into.
// False when t points off the surface at a boundary.
bool placeStart(const SurfaceMesh& m, Face& face, Vec3& b, Vec3& dir, const Vec3& t,
                const Vec3& ns);

// A face-plane direction carried onto the tangent plane of the smooth normal ns: unit,
// orthogonal to ns.
Vec3 toSmooth(const Vec3& dir, const Vec3& faceNormal, const Vec3& ns);

}  // namespace fgsg::rt::field::trace_detail
