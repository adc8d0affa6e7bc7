#include "runtime/field/trace_walk.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fgsg::rt::field::trace_detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The corner of a vertex in one face: the unit edges leaving it, counter-clockwise (ea
// first), and the angle between them.
struct Corner {
  Vec3 ea, eb;
  double angle;
};

Corner cornerAt(const SurfaceMesh& m, int f, int k) {
  const auto& t = m.faces[f];
  const Vec3& p = m.vertices[t[k]];
  Corner c;
  c.ea = m.vertices[t[(k + 1) % 3]] - p;
  c.eb = m.vertices[t[(k + 2) % 3]] - p;
  c.angle = std::atan2(c.ea.cross(c.eb).norm(), c.ea.dot(c.eb));
  const double na = c.ea.norm(), nb = c.eb.norm();
  if (na > 0) c.ea /= na;
  if (nb > 0) c.eb /= nb;
  return c;
}

// Around a vertex at corner k of face f: the face counter-clockwise next (across the edge
// to corner k + 2) and clockwise next (across the edge to corner k + 1); -1 at a boundary.
int ccwFace(const SurfaceMesh& m, int f, int k) { return m.neighbours[f][(k + 2) % 3]; }
int cwFace(const SurfaceMesh& m, int f, int k) { return m.neighbours[f][k]; }

// Where a counter-clockwise fan walk around v starts: f itself for an interior vertex,
// the clockwise-most face (its first edge on the boundary) for a boundary one.
int fanStart(const SurfaceMesh& m, int v, int f) {
  if (!m.boundaryVertex[v]) return f;
  int h = f;
  for (size_t guard = 0; guard < m.faces.size(); ++guard) {
    const int prev = cwFace(m, h, m.cornerOf(h, v));
    if (prev < 0 || prev == f) return prev < 0 ? h : f;
    h = prev;
  }
  return f;
}

}  // namespace

void Face::load(const SurfaceMesh& m, int face) {
  f = face;
  const auto& t = m.faces[face];
  for (int k = 0; k < 3; ++k) {
    v[k] = m.vertices[t[k]];
    vn[k] = m.vertexNormals[t[k]];
  }
  n = m.faceNormals[face];
  // Edge opposite corner i, running counter-clockwise.
  const Vec3 e[3] = {v[2] - v[1], v[0] - v[2], v[1] - v[0]};
  const double twiceArea = 2 * m.faceAreas[face];
  double longest2 = 0;
  for (const Vec3& x : e) longest2 = std::max(longest2, x.squaredNorm());
  degenerate = !(twiceArea > kDegenerateFace * longest2) || !std::isfinite(twiceArea);
  if (degenerate) {
    scale = height = 0;
    return;
  }
  const double inv = 1 / twiceArea;
  for (int i = 0; i < 3; ++i) {
    g[i] = n.cross(e[i]) * inv;
    g2[i] = e[i].squaredNorm() * inv * inv;
  }
  scale = std::sqrt(twiceArea);
  height = twiceArea / std::sqrt(longest2);
}

bool tangentPart(const Vec3& d, const Vec3& n, Vec3& out) {
  out = d - d.dot(n) * n;
  const double len = out.norm();
  if (!(len > 1e-12 * d.norm()) || !std::isfinite(len)) return false;
  out /= len;
  return true;
}

bool carryAcross(const SurfaceMesh& m, const Face& from, const Face& to, int i, Vec3& b,
                 Vec3& dir) {
  const int a = (i + 1) % 3, c = (i + 2) % 3;  // the edge runs from corner a to corner c
  const int ka = m.cornerOf(to.f, m.faces[from.f][a]), kc = m.cornerOf(to.f, m.faces[from.f][c]);
  if (ka < 0 || kc < 0 || to.degenerate) return false;
  // Unfold: the same components along the edge and across it (out of this face, into
  // the next), i.e. the rotation about the edge taking one face plane onto the other.
  const Vec3 e = (from.v[c] - from.v[a]).normalized();
  const Vec3 d = dir.dot(e) * e + dir.dot(from.n.cross(e)) * to.n.cross(e);
  Vec3 nb = Vec3::Zero();
  nb[ka] = b[a];
  nb[kc] = b[c];
  b = nb;  // b[i] == 0: the other two already sum to 1
  const double len = d.norm();
  dir = len > 0 ? Vec3(d / len) : e;
  return true;
}

bool crossEdge(const SurfaceMesh& m, Face& face, Vec3& b, Vec3& dir, int i) {
  const int g = m.neighbours[face.f][(i + 1) % 3];
  if (g < 0) return false;
  Face next;
  next.load(m, g);
  if (!carryAcross(m, face, next, i, b, dir)) return false;
  face = next;
  return true;
}

bool straightestThroughVertex(const SurfaceMesh& m, Face& face, Vec3& b, Vec3& dir, int k) {
  const int v = m.faces[face.f][k];
  // Where the curve came from, as an angle inside this face's corner.
  const Corner here = cornerAt(m, face.f, k);
  const Vec3 back = -dir;
  const double alpha =
      std::clamp(std::atan2(here.ea.cross(back).dot(face.n), here.ea.dot(back)), 0.0, here.angle);
  // Angles are measured counter-clockwise from the first edge of the fan walk's first face.
  const int first = fanStart(m, v, face.f);
  double total = 0, from = -1;
  bool closed = false;
  int h = first;
  for (size_t guard = 0; guard < m.faces.size(); ++guard) {
    const int kh = m.cornerOf(h, v);
    if (h == face.f) from = total + alpha;
    total += h == face.f ? here.angle : cornerAt(m, h, kh).angle;
    const int next = ccwFace(m, h, kh);
    if (next < 0) break;
    if (next == first) {
      closed = true;
      break;
    }
    h = next;
  }
  if (from < 0) return false;  // not a fan (cannot happen on a validated mesh)
  double target;
  if (closed) {
    target = from + total / 2;
    if (target >= total) target -= total;
  } else if (from + kPi <= total + kFanSlack) {
    target = std::min(from + kPi, total);
  } else if (from - kPi >= -kFanSlack) {
    target = std::max(from - kPi, 0.0);
  } else {
    return false;  // straight on leaves the surface
  }
  h = first;
  double acc = 0;
  for (size_t guard = 0; guard < m.faces.size(); ++guard) {
    const int kh = m.cornerOf(h, v);
    const Corner c = cornerAt(m, h, kh);
    const int next = ccwFace(m, h, kh);
    if (target <= acc + c.angle || next < 0 || next == first) {
      const double phi = std::clamp(target - acc, 0.0, c.angle);
      if (h != face.f) face.load(m, h);
      if (face.degenerate) return false;
      b = Vec3::Zero();
      b[kh] = 1;
      dir = std::cos(phi) * c.ea + std::sin(phi) * face.n.cross(c.ea);
      dir.normalize();
      return true;
    }
    acc += c.angle;
    h = next;
  }
  return false;
}

bool enterFan(const SurfaceMesh& m, int v, int f, const Vec3& t, const Vec3& nv, int& outFace,
              Vec3& outDir) {
  // Each face measures t by its angle from the corner's first edge, in its own plane.
  // Inside a corner: the face that holds t deepest. Outside all (the fan's angles do not
  // add up to the plane's, or t points off the surface): the nearest edge, which clamps
  // t when it is shared and stops the walk when it is the boundary.
  const int first = fanStart(m, v, f);
  double deepest = -1, nearest = std::numeric_limits<double>::infinity();
  bool nearestIsBoundary = false;
  Vec3 nearestEdge = Vec3::Zero();
  int nearestFace = -1;
  int h = first;
  for (size_t guard = 0; guard < m.faces.size(); ++guard) {
    const int kh = m.cornerOf(h, v);
    const Vec3& nh = m.faceNormals[h];
    const Corner c = cornerAt(m, h, kh);
    const int next = ccwFace(m, h, kh);
    Vec3 d;
    if (!tangentPart(carry(t, nv, nh), nh, d)) d = c.ea;
    const double beta = std::atan2(c.ea.cross(d).dot(nh), c.ea.dot(d));  // (-pi, pi]
    if (beta >= -kFanSlack && beta <= c.angle + kFanSlack) {
      const double depth = std::min(beta, c.angle - beta);
      if (depth > deepest) {
        deepest = depth;
        outFace = h;
        outDir = beta < 0 ? c.ea : (beta > c.angle ? c.eb : d);  // exactly inside
      }
    } else {
      // Past the first edge (clockwise of it) or past the second.
      const double pastA = beta < 0 ? -beta : 2 * kPi - beta;
      const double pastB = beta > c.angle ? beta - c.angle : beta + 2 * kPi - c.angle;
      if (std::min(pastA, pastB) < nearest) {
        nearest = std::min(pastA, pastB);
        nearestFace = h;
        nearestEdge = pastA <= pastB ? c.ea : c.eb;
        nearestIsBoundary = pastA <= pastB ? cwFace(m, h, kh) < 0 : next < 0;
      }
    }
    if (next < 0 || next == first) break;
    h = next;
  }
  if (deepest >= -kFanSlack) return true;
  if (nearestFace < 0 || nearestIsBoundary) return false;
  outFace = nearestFace;
  outDir = nearestEdge;
  return true;
}

bool placeStart(const SurfaceMesh& m, Face& face, Vec3& b, Vec3& dir, const Vec3& t,
                const Vec3& ns) {
  const int zeros = zeroCount(b);
  if (zeros >= 2) {
    const int v = m.faces[face.f][largest(b)];
    int h;
    Vec3 d;
    if (!enterFan(m, v, face.f, t, m.vertexNormals[v], h, d)) return false;
    if (h != face.f) face.load(m, h);
    if (face.degenerate) return false;
    b = Vec3::Zero();
    b[m.cornerOf(h, v)] = 1;
    dir = d;
    return true;
  }
  if (!tangentPart(carry(t, ns, face.n), face.n, dir)) dir = (face.v[1] - face.v[0]).normalized();
  if (zeros == 1) {
    const int i = b[0] == 0 ? 0 : (b[1] == 0 ? 1 : 2);
    // On an edge, pointing into the face across it: start there.
    if (face.leaves(face.rate(dir)[i], i)) return crossEdge(m, face, b, dir, i);
  }
  return true;
}

Vec3 toSmooth(const Vec3& dir, const Vec3& faceNormal, const Vec3& ns) {
  Vec3 out;
  if (tangentPart(carry(dir, faceNormal, ns), ns, out)) return out;
  // dir along ns (normals at right angles): any tangent will do.
  tangentPart(ns.cross(std::abs(ns.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()), ns, out);
  return out;
}

}  // namespace fgsg::rt::field::trace_detail
