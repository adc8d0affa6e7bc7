// Straightest geodesics (Polthier & Schmies 1998) and the angle helpers; field traces are
// in trace_field.cpp, the walk both share in trace_walk.cpp.
#include "runtime/field/trace.h"

#include "runtime/field/trace_walk.h"

#include <cmath>
#include <stdexcept>

namespace fgsg::rt::field {

using namespace trace_detail;

double orientedAngle(const Vec3& a, const Vec3& b, const Vec3& n) {
  const Vec3 at = a - a.dot(n) * n, bt = b - b.dot(n) * n;
  const double s = at.cross(bt).dot(n), c = at.dot(bt);
  if (s == 0 && c == 0) return 0;
  const double angle = std::atan2(s, c);
  return angle == -3.14159265358979323846 ? -angle : angle;  // (-pi, pi]
}

Vec3 rotateAbout(const Vec3& v, const Vec3& n, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * v + s * n.cross(v) + (1 - c) * n.dot(v) * n;
}

TraceResult traceGeodesic(const SurfaceMesh& m, SurfacePoint start, Vec3 dir, double length,
                          Deadline* deadline) {
  if (start.face < 0 || size_t(start.face) >= m.faces.size())
    throw std::invalid_argument("traceGeodesic: the start is not a face of the mesh");
  if (!(length > 0)) length = 0;  // NaN too
  TraceResult r;
  Face face;
  face.load(m, start.face);
  Vec3 b = cleanBary(start.bary);
  r.end = {face.f, b};
  const Vec3 ns = r.end.normal(m);
  Vec3 t;
  if (!tangentPart(dir, ns, t)) t = toSmooth(face.v[1] - face.v[0], face.n, ns);
  r.direction = t;
  if (face.degenerate || !placeStart(m, face, b, dir, t, ns)) {
    r.stopped = length > 0;
    return r;
  }
  double remaining = length, minHeight = face.height;
  for (size_t step = 1; remaining > 0; ++step) {
    if (deadline) deadline->check();
    if (step > kIterBase + kIterPerHeight * length / minHeight) {
      r.stopped = true;
      break;
    }
    const Vec3 rate = face.rate(dir);
    const Exit exit = exitOf(face, b, rate);
    if (exit.t >= remaining) {
      b = cleanBary(b + remaining * rate);
      r.length += remaining;
      remaining = 0;
      break;
    }
    b += exit.t * rate;
    b[exit.i] = 0;
    b = cleanBary(b);
    r.length += exit.t;
    remaining -= exit.t;
    const int from = face.f;
    if (zeroCount(b) >= 2) {
      if (!straightestThroughVertex(m, face, b, dir, largest(b))) {
        r.stopped = true;
        break;
      }
      r.crossings += face.f != from;
    } else {
      if (!crossEdge(m, face, b, dir, exit.i)) {
        r.stopped = true;
        break;
      }
      ++r.crossings;
    }
    minHeight = std::min(minHeight, face.height);
  }
  r.end = {face.f, b};
  r.direction = toSmooth(dir, face.n, r.end.normal(m));
  return r;
}

}  // namespace fgsg::rt::field
