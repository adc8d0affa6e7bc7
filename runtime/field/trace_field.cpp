// (Hyper)streamlines at an angle to a field (FGSG §4.3), with the reflection heuristic at
// wedges and trisectors (Fig. 9). Within a face the curve is integrated with RK4 on the
// field as the field itself answers it (its own interpolation, whatever that is); where
// a step leaves the face, RK4's continuous extension says where the curve meets the edge
// (no extra field queries), and the walk crosses there.
#include "runtime/field/trace.h"

#include "runtime/field/trace_walk.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fgsg::rt::field {

using namespace trace_detail;

namespace {

// The longest RK4 step, relative to the face size (sqrt of twice its area): fields vary
// over about a face, and a face a step keeps a circle of 8 faces' radius closed to 1e-4
// of its radius after a turn.
constexpr double kFieldStep = 1.0;
// A step is aimed this far past where its first tangent's line leaves the face, so that
// the curve leaves near the end of the step, where the continuous extension is nearly as
// good as the step itself (and stages beyond the edge are just across it); but no
// shorter than kAimFloor of the longest step, lest a curve skimming an edge crawl.
constexpr double kAimPast = 1.05;
constexpr double kAimFloor = 0.25;
// A chord shorter than this (of a unit-speed step) means the field turned by about 105
// degrees or more within the step: the step is halved, down to kStepFloor of the face
// size. A field still turning that fast there has a zero in the step: a vector field's
// streamline ends at it (a sink, or a saddle reached along its separatrix); a line
// field's (an unlisted degenerate point) takes a plain Euler step across it. (Gentler
// turns are left to RK4: on real meshes they are mostly the surface bending under the
// field, and halving for them costs a fifth more field queries.) The floor places a
// zero to a thousandth of a face, far below anything a grammar places there.
constexpr double kShortChord = 0.8;
constexpr double kStepFloor = 1e-3;
// A vector field turning by more than 120 degrees between two steps: the curve ran
// through a zero of the field and ends there. A line field has no such turn (its sign
// follows the curve).
constexpr double kReversal = -0.5;
// Consecutive crossings without moving (a point on an edge, the field pointing across
// it) before the curve slides along the edge instead.
constexpr int kMaxZeroHops = 4;
// A field direction shorter than this after being carried into a face plane is none.
constexpr double kTinyDirection = 1e-12;
// Newton on the continuous extension stops when its bracket or its update is this small
// (a fraction of the step): rounding level.
constexpr double kRootTolerance = 1e-14;
// An RK stage beyond the face is found by unfolding across at most this many edges (a
// stage lies within one step, about a face, of the point); further on, where it stops.
constexpr int kStageHops = 4;

// How the reflection heuristic treats a degenerate point: +1 wedge (negative oriented
// angle), -1 trisector (same angle), 0 not at all.
int reflection(const Degeneracy& d) {
  if (d.kind == Degeneracy::Wedge) return 1;
  if (d.kind == Degeneracy::Trisector) return -1;
  if (d.kind == Degeneracy::Other && (d.indexTimesTwo == 1 || d.indexTimesTwo == -1))
    return d.indexTimesTwo;
  return 0;
}

bool hasReflectable(const std::vector<Degeneracy>& ds) {
  for (const Degeneracy& d : ds)
    if (reflection(d)) return true;
  return false;
}

// The first s in [0, sEnd] at which x0 + s m is within eps of c, for a curve coming
// closer; -1 when none.
double discHit(const Vec3& x0, const Vec3& m, const Vec3& c, double eps, double sEnd) {
  const Vec3 w = x0 - c;
  const double a = m.squaredNorm(), half = w.dot(m), q = w.squaredNorm() - eps * eps;
  if (half >= 0 || !(a > 0)) return -1;  // moving away
  if (q <= 0) return 0;
  const double disc = half * half - a * q;
  if (disc < 0) return -1;
  const double s = (-half - std::sqrt(disc)) / a;
  return s <= sEnd ? s : -1;
}

// One RK4 step: the stage tangents over arc length h. The step's displacement is h times
// the mean tangent; at fraction s of the step the classical third-order continuous
// extension gives h (w0 k1 + w1 (k2 + k3) + w2 k4), weights below.
struct Stages {
  Vec3 k[4];
  Vec3 r[4];  // the barycentric rates of k in the face
  double h = 0;

  Vec3 mean() const { return (k[0] + 2 * (k[1] + k[2]) + k[3]) / 6; }
  static void weights(double s, double w[3]) {
    const double s2 = s * s, s3 = s2 * s;
    w[0] = s - 1.5 * s2 + 2 * s3 / 3;
    w[1] = s2 - 2 * s3 / 3;
    w[2] = -0.5 * s2 + 2 * s3 / 3;
  }
  static void slopes(double s, double w[3]) {
    w[0] = 1 - 3 * s + 2 * s * s;
    w[1] = 2 * s - 2 * s * s;
    w[2] = -s + 2 * s * s;
  }
  // The position (in rates r of the stages) and the tangent at fraction s.
  Vec3 at(const Vec3& b, const Vec3 r[4], double s) const {
    double w[3];
    weights(s, w);
    return b + h * (w[0] * r[0] + w[1] * (r[1] + r[2]) + w[2] * r[3]);
  }
  Vec3 tangent(double s) const {
    double w[3];
    slopes(s, w);
    return w[0] * k[0] + w[1] * (k[1] + k[2]) + w[2] * k[3];
  }
  void euler(const Vec3& d, const Vec3& rate, double step) {
    k[0] = k[1] = k[2] = k[3] = d;
    r[0] = r[1] = r[2] = r[3] = rate;
    h = step;
  }
};

// The first fraction s in (0, 1] of a step at which the coordinate that is b0 >= 0 at
// s = 0 and negative at s = 1 reaches zero, along the continuous extension (a cubic in
// s; rates a, c = the two middle stages together, d): safeguarded Newton.
double crossingFraction(const Stages& st, double b0, double a, double c, double d) {
  auto value = [&](double s, double& slope) {
    double w[3], dw[3];
    Stages::weights(s, w);
    Stages::slopes(s, dw);
    slope = st.h * (dw[0] * a + dw[1] * c + dw[2] * d);
    return b0 + st.h * (w[0] * a + w[1] * c + w[2] * d);
  };
  double lo = 0, hi = 1, slope;
  const double end = value(1, slope);
  double s = b0 / (b0 - end);  // where the chord crosses
  for (int round = 0; round < 30 && hi - lo > kRootTolerance; ++round) {
    const double v = value(s, slope);
    (v > 0 ? lo : hi) = s;
    if (v == 0) break;
    const double next = slope != 0 ? s - v / slope : 0.5 * (lo + hi);
    const double was = s;
    s = next > lo && next < hi ? next : 0.5 * (lo + hi);
    if (std::abs(s - was) <= kRootTolerance) break;
  }
  return s;
}

class Streamline {
 public:
  Streamline(const SurfaceMesh& m, const DirectionField& field, double angle, Deadline* deadline)
      : m_(m), field_(field), line_(field.isLineField()), deadline_(deadline) {
    setAngle(angle);
  }

  TraceResult run(SurfacePoint start, const Vec3& initialDir, double length);

 private:
  void setAngle(double a) {
    cosA_ = std::cos(a);
    sinA_ = std::sin(a);
  }
  // The field's unit direction at barycentric b (inside) of `face`, in the face plane.
  bool fieldAt(const Face& face, const Vec3& b, Vec3& out) const;
  // The field at the point reached from barycentric b of `face` by moving `disp` (in the
  // face plane) straight on: unfolded across the edges it meets (an RK stage beyond the
  // face), the direction there brought back the same way into this face's plane.
  bool fieldAlong(const Face& face, const Vec3& b, const Vec3& db, const Vec3& disp,
                  Vec3& out) const;
  // Face g, loaded (null when degenerate): faces around the curve are asked for again
  // and again (stages beyond an edge, then the crossing), so a few are kept.
  const Face* faceOf(int g) const;
  // The face across the edge opposite corner i of `face` (null at the boundary).
  const Face* across(const Face& face, int i) const {
    const int g = m_.neighbours[face.f][(i + 1) % 3];
    return g < 0 ? nullptr : faceOf(g);
  }
  // The curve's tangent from the field direction f (the field turned by the angle), on
  // ref's side for a line field.
  Vec3 turn(const Vec3& f, const Vec3& n, const Vec3& ref) const {
    const Vec3 t = cosA_ * f + sinA_ * n.cross(f);
    return line_ && t.dot(ref) < 0 ? Vec3(-t) : t;
  }
  bool tangentAt(const Face& face, const Vec3& b, const Vec3& ref, Vec3& out) const {
    Vec3 f;
    if (!fieldAt(face, b, f)) return false;
    out = turn(f, face.n, ref);
    return true;
  }
  // db: the displacement's barycentric change.
  bool tangentAlong(const Face& face, const Vec3& b, const Vec3& db, const Vec3& disp,
                    const Vec3& ref, Vec3& out) const {
    Vec3 f;
    if (!fieldAlong(face, b, db, disp, f)) return false;
    out = turn(f, face.n, ref);
    return true;
  }
  // RK4 stages over arc length h from b (k1 the tangent there); Euler where the field
  // has no direction at a stage.
  void stages(const Face& face, const Vec3& b, const Vec3& k1, double h, Stages& st) const {
    st.h = h;
    st.k[0] = k1;
    st.r[0] = face.rate(k1);
    for (int j = 1; j < 4; ++j) {
      const double c = j == 3 ? h : 0.5 * h;
      if (!tangentAlong(face, b, c * st.r[j - 1], c * st.k[j - 1], k1, st.k[j])) {
        st.euler(k1, st.r[0], h);
        return;
      }
      st.r[j] = face.rate(st.k[j]);
    }
  }
  double stepIn(const Face& face, double remaining) const {
    return std::min(remaining, kFieldStep * face.scale);
  }
  // Moves into the face across edge i (b_[i] == 0); reuses the face loaded for stages.
  bool crossInto(int i);
  // On an edge with the step pointing over it: true when the face across takes the
  // curve (its own step from there enters it); then face_, b_, dir_ move there.
  bool hopAcross(int i, double remaining);
  // The vertex at corner k: moves into the fan face the field points into.
  bool leaveVertex(int k);
  // The reflection heuristic at degenerate point d (kind +1 wedge, -1 trisector) from
  // the current point; may end the trace inside the jump.
  bool jump(const Degeneracy& d, int kind, double& remaining, TraceResult& r);

  const SurfaceMesh& m_;
  const DirectionField& field_;
  const bool line_;
  Deadline* deadline_;  // null: no time limit
  double cosA_ = 1, sinA_ = 0;
  Face face_;
  Vec3 b_, dir_;
  bool endedInJump_ = false;
  static constexpr int kCachedFaces = 16;  // direct-mapped by face index
  mutable Face cache_[kCachedFaces];
};

bool Streamline::fieldAt(const Face& face, const Vec3& b, Vec3& out) const {
  Vec3 c = b;
  if (!(c.minCoeff() >= 0)) {  // rounding may leave a coordinate a hair below zero
    c = c.cwiseMax(0.0);
    const double sum = c.sum();
    if (!(sum > 0)) return false;
    c /= sum;
  }
  Vec3 f;
  if (!field_.direction({face.f, c}, f)) return false;
  out = carry(f, face.smoothNormal(c), face.n);
  out -= out.dot(face.n) * face.n;
  const double len2 = out.squaredNorm();  // NaN fails here too
  if (!(len2 > kTinyDirection * kTinyDirection) || !std::isfinite(len2)) return false;
  if (std::abs(len2 - 1) > 1e-14) out /= std::sqrt(len2);  // fields answer unit vectors
  return true;
}

const Face* Streamline::faceOf(int g) const {
  Face& slot = cache_[g % kCachedFaces];
  if (slot.f != g) slot.load(m_, g);
  return slot.degenerate ? nullptr : &slot;
}

bool Streamline::fieldAlong(const Face& face, const Vec3& b, const Vec3& db, const Vec3& disp,
                            Vec3& out) const {
  const Vec3 target = b + db;
  if (target.minCoeff() >= 0) return fieldAt(face, target, out);
  // Just past one edge (the usual case): unfold the point about it into the face there.
  const int i = target[0] < 0 ? 0 : (target[1] < 0 ? 1 : 2);
  if ((target.array() < 0).count() == 1) {
    if (const Face* g = across(face, i)) {
      const Vec3& a = face.v[(i + 1) % 3];
      const Vec3 x = a + carry(face.at(target) - a, face.n, g->n);
      Vec3 c;
      for (int k = 0; k < 3; ++k) c[k] = g->g[k].dot(x - g->v[(k + 1) % 3]);
      Vec3 f;
      if (c.minCoeff() >= -kSnap) {
        if (!fieldAt(*g, c, f)) return false;
        out = carry(f, g->n, face.n);  // fold back about the edge
        return true;
      }
    }
  }
  // Further: walk there, each edge met unfolding the rest of the way into the next face.
  struct Fold {
    Vec3 e, from, to;  // the edge's direction, and the normals on either side
  } folds[kStageHops];
  int count = 0;
  const Face* here = &face;
  Face reached;
  Vec3 at = b, dir = disp;
  double left = dir.norm();
  if (!(left > 0)) return fieldAt(face, b, out);
  dir /= left;
  for (;;) {
    const Vec3 rate = here->rate(dir);
    const Exit e = exitOf(*here, at, rate);
    if (e.t >= left) {
      at += left * rate;
      break;
    }
    at += e.t * rate;
    at[e.i] = 0;
    at = cleanBary(at);
    left -= e.t;
    if (count == kStageHops || zeroCount(at) >= 2) break;  // far enough, or a vertex
    const Face* next = across(*here, e.i);
    const Vec3 edge = (here->v[(e.i + 2) % 3] - here->v[(e.i + 1) % 3]).normalized();
    if (!next || !carryAcross(m_, *here, *next, e.i, at, dir)) break;  // the boundary
    folds[count++] = {edge, here->n, next->n};
    reached = *next;  // a copy: the next face asked for may take its cache slot
    here = &reached;
  }
  Vec3 f;
  if (!fieldAt(*here, at, f)) return false;
  // Fold back: the inverse rotations about the edges, last first.
  for (int k = count - 1; k >= 0; --k) {
    const Fold& fd = folds[k];
    f = f.dot(fd.e) * fd.e + f.dot(fd.to.cross(fd.e)) * fd.from.cross(fd.e);
  }
  out = f;
  return true;
}

bool Streamline::crossInto(int i) {
  const Face* ahead = across(face_, i);
  if (!ahead || !carryAcross(m_, face_, *ahead, i, b_, dir_)) return false;
  face_ = *ahead;
  return true;
}

bool Streamline::hopAcross(int i, double remaining) {
  const Face* ahead = across(face_, i);
  if (!ahead) return false;
  const Face g = *ahead;
  Vec3 b = b_, d = dir_, k1;
  if (!carryAcross(m_, face_, g, i, b, d) || !tangentAt(g, b, d, k1)) return false;
  const int j = b[0] == 0 ? 0 : (b[1] == 0 ? 1 : 2);
  Stages st;
  stages(g, b, k1, stepIn(g, remaining), st);
  if (g.leaves(g.rate(st.mean())[j], j)) return false;
  face_ = g;
  b_ = b;
  dir_ = d;
  return true;
}

bool Streamline::leaveVertex(int k) {
  const int v = m_.faces[face_.f][k];
  Vec3 b = Vec3::Zero(), f, t;
  b[k] = 1;
  const Vec3& nv = m_.vertexNormals[v];
  if (!field_.direction({face_.f, b}, f) || !tangentPart(f, nv, f)) return false;
  t = cosA_ * f + sinA_ * nv.cross(f);
  if (line_ && t.dot(dir_) < 0) t = -t;
  int h;
  Vec3 d;
  if (!enterFan(m_, v, face_.f, t, nv, h, d)) return false;
  if (h != face_.f) {
    const Face* g = faceOf(h);
    if (!g) return false;
    face_ = *g;
  }
  b_ = Vec3::Zero();
  b_[m_.cornerOf(h, v)] = 1;
  dir_ = d;
  return true;
}

bool Streamline::jump(const Degeneracy& d, int kind, double& remaining, TraceResult& r) {
  const Vec3 bd = cleanBary(d.at.bary);
  // p' = 2d - p, pulled back along the line through d onto the face when outside it.
  double s = 1;
  for (int i = 0; i < 3; ++i)
    if (b_[i] > 2 * bd[i]) s = std::min(s, bd[i] / (b_[i] - bd[i]));
  const Vec3 bp = cleanBary(bd + s * (bd - b_));
  const Vec3 jumpVec = face_.at(bp) - face_.at(b_);
  const double len = jumpVec.norm();
  if (!(len > 0)) return false;
  const Vec3 across = jumpVec / len;
  const double in = orientedAngle(across, dir_, face_.n);
  const Vec3 out = rotateAbout(across, face_.n, kind > 0 ? -in : in);
  if (remaining <= len) {  // ends on the way across
    b_ = cleanBary(b_ + (remaining / len) * (bp - b_));
    dir_ = across;
    r.length += remaining;
    remaining = 0;
    endedInJump_ = true;
    return true;
  }
  b_ = bp;
  dir_ = out;
  r.length += len;
  remaining -= len;
  // The new angle: the outgoing direction against the field at p'.
  Vec3 f;
  if (!fieldAt(face_, b_, f)) return false;
  if (line_ && f.dot(out) < 0) f = -f;
  setAngle(orientedAngle(f, out, face_.n));
  return true;
}

TraceResult Streamline::run(SurfacePoint start, const Vec3& initialDir, double length) {
  TraceResult r;
  face_.load(m_, start.face);
  b_ = cleanBary(start.bary);
  r.end = {face_.f, b_};
  const Vec3 ns = r.end.normal(m_);
  Vec3 fallback;
  if (!tangentPart(initialDir, ns, fallback))
    fallback = toSmooth(face_.v[1] - face_.v[0], face_.n, ns);
  r.direction = fallback;
  Vec3 f;
  if (face_.degenerate || !field_.direction(r.end, f) || !tangentPart(f, ns, f)) {
    r.stopped = length > 0;
    return r;
  }
  Vec3 t = cosA_ * f + sinA_ * ns.cross(f);
  if (line_ && t.dot(initialDir) < 0) {
    t = -t;
    f = -f;
  }
  r.direction = t;
  r.fieldDirection = f;
  if (!placeStart(m_, face_, b_, dir_, t, ns)) {
    r.stopped = length > 0;
    return r;
  }

  double remaining = length, minHeight = face_.height;
  int visiting = -1, jumpedIn = -1, zeroHops = 0;
  bool atVertexPlaced = zeroCount(b_) >= 2;  // placeStart chose the fan face already
  const std::vector<Degeneracy>* degeneracies = nullptr;
  bool singular = false;
  Stages st;
  for (size_t step = 1; remaining > 0; ++step) {
    if (deadline_) deadline_->check();
    if (face_.f != visiting) {
      visiting = face_.f;
      jumpedIn = -1;  // a new visit may jump again
      degeneracies = &field_.degeneraciesIn(visiting);
      singular = hasReflectable(*degeneracies);
      minHeight = std::min(minHeight, face_.height);
    }
    if (step > kIterBase + kIterPerHeight * length / minHeight) {
      r.stopped = true;
      break;
    }
    const int zeros = zeroCount(b_);
    if (zeros >= 2 && !atVertexPlaced) {
      const int from = face_.f;
      if (!leaveVertex(largest(b_))) {
        r.stopped = true;
        break;
      }
      r.crossings += face_.f != from;
      atVertexPlaced = true;
      continue;
    }

    // Within the jump radius of a degenerate point the field turns fast: smaller steps
    // there, which also keeps the disc test below from stepping over it.
    double h = stepIn(face_, remaining);
    const bool nearSingular = singular && jumpedIn != face_.f;
    if (nearSingular) h = std::min(h, kJumpRadius * face_.scale);
    Vec3 k1;
    if (!tangentAt(face_, b_, dir_, k1) || (!line_ && step > 1 && k1.dot(dir_) < kReversal)) {
      r.stopped = true;
      break;
    }
    // Aimed just past where k1's line leaves the face (kAimPast).
    const Exit aim = exitOf(face_, b_, face_.rate(k1));
    if (aim.t * kAimPast < h)
      h = std::max(aim.t * kAimPast, std::min(h, kAimFloor * kFieldStep * face_.scale));
    stages(face_, b_, k1, h, st);
    Vec3 mv = st.mean();
    if (mv.norm() < kShortChord) {
      bool resolved = false;
      while (!resolved && 0.5 * st.h >= kStepFloor * face_.scale) {
        stages(face_, b_, k1, 0.5 * st.h, st);
        mv = st.mean();
        resolved = mv.norm() >= kShortChord;
      }
      if (!resolved && !line_) {
        r.stopped = true;  // a zero of the vector field within the smallest step
        break;
      }
      if (!resolved) st.euler(k1, face_.rate(k1), h);  // across an unlisted degenerate point
      mv = st.mean();
      h = st.h;
    }
    // On an edge or a vertex with the step pointing off the face: cross when the face
    // beyond takes the curve, else slide along the edge (both sides point at it).
    bool constrained = false, hopped = false;
    for (int i = 0; i < 3; ++i) {
      if (b_[i] != 0 || !face_.leaves(face_.rate(mv)[i], i)) continue;
      if (zeros == 1 && zeroHops < kMaxZeroHops && hopAcross(i, remaining)) {
        hopped = true;
        break;
      }
      mv -= (mv.dot(face_.g[i]) / face_.g2[i]) * face_.g[i];
      constrained = true;
    }
    if (hopped) {
      ++zeroHops;
      ++r.crossings;
      atVertexPlaced = false;
      continue;
    }
    if (constrained) {
      const double len = mv.norm();
      const Vec3 rate = face_.rate(mv);
      bool still = false;
      for (int i = 0; i < 3; ++i) still |= b_[i] == 0 && face_.leaves(rate[i] / len, i);
      if (len > 1e-9 && !still) {
        st.euler(mv / len, rate / len, h);
      } else if (zeros >= 2) {
        st.euler(dir_, face_.rate(dir_), h);  // the fan's choice, inside the corner
      } else {
        r.stopped = true;  // the field points straight into the edge from both sides
        break;
      }
      mv = st.mean();
    }

    // Where the step ends, or where it first leaves the face on the way.
    const Vec3* rates = st.r;
    const Vec3 end = st.at(b_, rates, 1);
    double sExit = 1;
    int exitI = -1;
    for (int i = 0; i < 3; ++i) {
      if (!face_.leaves(end[i] / h, i)) continue;  // stays, or runs along it
      const double s = b_[i] > 0 ? crossingFraction(st, b_[i], rates[0][i],
                                                    rates[1][i] + rates[2][i], rates[3][i])
                                 : 0;
      if (s < sExit || exitI < 0) {
        sExit = s;
        exitI = i;
      }
    }
    const bool cross = exitI >= 0;
    const double s = cross ? sExit * h : h;

    // Reflection heuristic: the first wedge or trisector of this face whose jump disc
    // the step enters (once a visit).
    if (nearSingular) {
      const Vec3 x0 = face_.at(b_);
      const double eps = kJumpRadius * face_.scale;
      double first = -1;
      const Degeneracy* hit = nullptr;
      for (const Degeneracy& d : *degeneracies) {
        if (!reflection(d) || d.at.face != face_.f) continue;
        const double sh = discHit(x0, mv, face_.at(d.at.bary), eps, s);
        if (sh >= 0 && (first < 0 || sh < first)) {
          first = sh;
          hit = &d;
        }
      }
      if (hit) {
        b_ = cleanBary(b_ + first * face_.rate(mv));
        r.length += first;
        remaining -= first;
        // Coming in: the curve's tangent at p_n.
        if (mv.norm() > 0) dir_ = mv.normalized();
        Vec3 in;
        if (tangentAt(face_, b_, dir_, in)) dir_ = in;
        jumpedIn = face_.f;
        zeroHops = 0;
        atVertexPlaced = false;
        if (remaining <= 0) break;
        if (!jump(*hit, reflection(*hit), remaining, r)) {
          r.stopped = true;
          break;
        }
        continue;
      }
    }

    Vec3 nb = st.at(b_, rates, cross ? sExit : 1);
    if (cross) nb[exitI] = 0;
    b_ = cleanBary(nb);
    const Vec3 tangent = st.tangent(cross ? sExit : 1);
    if (tangent.norm() > 0) dir_ = (tangent - tangent.dot(face_.n) * face_.n).normalized();
    r.length += s;
    remaining -= s;
    if (s > 0) zeroHops = 0;
    atVertexPlaced = false;
    if (!cross || remaining <= 0) continue;
    if (zeroCount(b_) >= 2) continue;  // on a vertex: the next turn picks the fan face
    if (!crossInto(exitI)) {
      r.stopped = true;
      break;
    }
    ++r.crossings;
  }

  r.end = {face_.f, b_};
  const Vec3 ne = r.end.normal(m_);
  const Vec3 travel = toSmooth(dir_, face_.n, ne);
  r.direction = travel;
  r.fieldDirection = Vec3::Zero();
  if (field_.direction(r.end, f) && tangentPart(f, ne, f)) {
    t = cosA_ * f + sinA_ * ne.cross(f);
    const bool flip = line_ && (endedInJump_ ? f.dot(travel) : t.dot(travel)) < 0;
    if (flip) {
      t = -t;
      f = -f;
    }
    if (!endedInJump_) r.direction = t;
    r.fieldDirection = f;
  }
  return r;
}

}  // namespace

TraceResult traceField(const SurfaceMesh& m, const DirectionField& field, SurfacePoint start,
                       Vec3 initialDir, double angle, double length, Deadline* deadline) {
  if (start.face < 0 || size_t(start.face) >= m.faces.size())
    throw std::invalid_argument("traceField: the start is not a face of the mesh");
  if (!(length > 0)) length = 0;
  if (!std::isfinite(angle)) angle = 0;
  return Streamline(m, field, angle, deadline).run(start, initialDir, length);
}

}  // namespace fgsg::rt::field
