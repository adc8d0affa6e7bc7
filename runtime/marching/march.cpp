// MarchingSurface::march: a straight line in the image, face by face within a chart
// (chart_walk.h), jumping through indirection pointers where it leaves the chart
// (seam_jump.cpp), until the length is used up.
#include "runtime/marching/marching_surface_impl.h"

#include <cmath>

namespace fgsg::rt::marching {

namespace {

// A surface-length march gives up once its path is this many times the length without
// getting that far from the start (on a sphere the path is at most pi/2 times the chord).
constexpr double kMaxPathPerLength = 8;
constexpr int kMaxPieces = 1 << 22;
// Pieces shorter than this (texels) make no progress: turning around a vertex, a jump
// whose landing leaves its face at once. This many in a row end the march.
constexpr double kStillTexels = 1e-12;
constexpr int kMaxStillPieces = 4096;
// Image-length marches at least this long try the coarse levels first.
constexpr double kCoarseMinTexels = 8;

MarchPoint marchPoint(const MarchingSurface::Impl& s, const ChartPoint& p, const Vec2& d) {
  MarchPoint m;
  m.at.face = p.face;
  m.at.bary = p.bary;
  m.image = s.triangles[p.face].imagePoint(p.bary);
  m.chart = s.triangles[p.face].chart;
  m.dir = d;
  return m;
}

// The first parameter tau in [0, 1] where a + tau (b - a) is `radius` away from c, given
// that a is closer than that; > 1 when the piece stays closer.
double leavesBall(const Vec3& a, const Vec3& b, const Vec3& c, double radius) {
  const Vec3 w = a - c, v = b - a;
  const double A = v.squaredNorm(), B = w.dot(v), C = w.squaredNorm() - radius * radius;
  if (C >= 0) return 0;
  if (A == 0) return 2;
  const double root = std::sqrt(B * B - A * C);  // > |B| since C < 0
  // The positive root, written so that it never cancels.
  const double tau = B > 0 ? -C / (B + root) : (root - B) / A;
  return tau;
}

}  // namespace

bool MarchingSurface::march(const MarchPoint& from, double length, LengthUnit unit, MarchPoint& to) const {
  return march(from, length, unit, to, nullptr);
}

bool MarchingSurface::march(const MarchPoint& from, double length, LengthUnit unit, MarchPoint& to,
                            MarchTrace* trace) const {
  const Impl& s = *impl_;
  MarchTrace local;
  MarchTrace& tr = trace ? *trace : local;
  tr = MarchTrace{};
  to = from;
  if (from.at.face < 0 || from.at.face >= int(s.triangles.size()) || !from.at.bary.allFinite() ||
      !from.dir.allFinite() || !(from.dir.norm() > 0) || !std::isfinite(length)) {
    tr.end = MarchEnd::Refused;
    return false;
  }
  ChartPoint p{from.at.face, tidyBary(from.at.bary)};
  Vec2 d = from.dir.normalized();
  to = marchPoint(s, p, d);
  if (length <= 0) return true;

  const Vec3 start = surfacePoint(s.mesh, p);
  double remaining = length;  // texels (Image)
  double path = 0;            // 3D path length so far (Surface)
  int still = 0;
  bool newChart = true;  // the coarse look pays only where a chart's line begins
  MarchEnd stop = MarchEnd::FaceLimit;  // unless the loop stops otherwise
  while (tr.pieces < kMaxPieces) {
    ++tr.pieces;
    const ImageTriangle& t = s.triangles[p.face];
    if (unit == LengthUnit::Image && newChart && remaining >= kCoarseMinTexels) {
      newChart = false;
      // Fig. 3 A in one look: the whole rest of the line inside the chart's texels. The
      // face under its end is found from that texel's own face, walking to the end.
      const Vec2 here = t.imagePoint(p.bary), end = here + remaining * d;
      if (s.image.segmentInChart(here, end, t.chart)) {
        MarchPoint q;
        if (locate(end, d, q)) {
          tr.coarse = true;
          to = q;
          return true;
        }
      }
    }
    const FaceExit e = faceExit(t, p.bary, d);
    if (e.edge < 0) {  // no direction in this face: cannot happen for a unit d
      stop = MarchEnd::NoProgress;
      break;
    }
    const Vec3 rate = t.baryRate(d);
    Vec3 exitBary = p.bary + e.length * rate;
    exitBary[e.corner] = 0;
    exitBary = tidyBary(exitBary);
    if (unit == LengthUnit::Image) {
      if (remaining <= e.length) {
        p.bary = tidyBary(p.bary + remaining * rate);
        to = marchPoint(s, p, d);
        return true;
      }
      remaining -= e.length;
    } else {
      const Vec3 a = surfacePoint(s.mesh, p), b = surfacePoint(s.mesh, ChartPoint{p.face, exitBary});
      const double tau = leavesBall(a, b, start, length);
      if (tau <= 1) {
        p.bary = tidyBary(p.bary + tau * (exitBary - p.bary));
        to = marchPoint(s, p, d);
        return true;
      }
      path += (b - a).norm();
      if (path > kMaxPathPerLength * length) {
        p.bary = exitBary;
        stop = MarchEnd::PathTooLong;
        break;
      }
    }
    p.bary = exitBary;
    still = e.length > kStillTexels ? 0 : still + 1;
    if (still > kMaxStillPieces) {
      stop = MarchEnd::NoProgress;
      break;
    }
    const int g = t.continuation[e.edge];
    if (g >= 0) {
      p.bary = baryAcross(s.mesh, p.face, e.edge, p.bary, g);
      p.face = g;
      continue;
    }
    SeamJump jump;
    if (!jumpAcrossSeam(s, p.face, e.edge, p.bary, d, jump)) {
      to = marchPoint(s, p, d);
      tr.end = MarchEnd::Boundary;
      return false;
    }
    ++(jump.viaPointer ? tr.pointerJumps : tr.adjacencyJumps);
    p = jump.landing;
    d = jump.dir;
    newChart = true;
  }
  to = marchPoint(s, p, d);
  tr.end = stop;
  return false;
}

}  // namespace fgsg::rt::marching
