// Moving on the surface (FGSG §4.3, "Guiding the translation command"): a translation in
// the tangent plane becomes a curve on the triangle mesh. Without a field it is the
// straightest geodesic (Polthier & Schmies); with one it is the (hyper)streamline that
// keeps a fixed oriented angle to the field, passing through wedges and trisectors of a
// line field by the paper's reflection heuristic (Fig. 9).
//
// Every trace walks one face at a time in barycentric coordinates, so its end is always a
// valid surface point; it crosses edges exactly, passes through vertices, stops at the
// boundary, and ends after a bounded number of steps. Same inputs, same result; no state
// is shared, so traces may run in parallel (over a field that may be queried so).
// A start whose face is not the mesh's throws std::invalid_argument; a length that is not
// positive (or NaN) traces nothing.
#pragma once

#include "runtime/deadline.h"
#include "runtime/field/direction_field.h"

namespace fgsg::rt::field {

// The jump radius of the reflection heuristic, relative to the size (sqrt of twice the
// area) of the face holding the degenerate point: a curve coming this close jumps across
// it. Small enough that the disc stays mostly inside the face and only curves that would
// otherwise be bent right round by the singularity jump; large enough to catch them
// before they are (the tracer steps at most this far at a time in such a face).
constexpr double kJumpRadius = 0.2;

struct TraceResult {
  SurfacePoint end;  // where the trace stopped
  // The unit tangent of the curve at the end (world).
  Vec3 direction = Vec3::Zero();
  // The field's direction at the end, its sign continuous with the trace (zero without a
  // field, or where the field has no direction).
  Vec3 fieldDirection = Vec3::Zero();
  double length = 0;     // arc length travelled (== requested unless stopped)
  int crossings = 0;     // triangle edges crossed (a pass through a vertex counts one)
  bool stopped = false;  // ended early: the mesh boundary, or no direction (a zero field)
};

// `direction` and `fieldDirection` lie in the tangent plane of the smooth normal at the
// end, end.normal(mesh): the curve runs in face planes and its tangent is carried onto
// that plane by the minimal rotation, which keeps oriented angles. Input directions are
// taken the same way: their part tangent to start.normal(mesh).

// Without a field: the straightest geodesic leaving `start` in tangent direction `dir`,
// for arc length `length` (unfolded across each edge; through a vertex it leaves with
// half the vertex's angle sum on either side; through a boundary vertex it goes straight
// on when the fan has room for it on one side, else it stops there).
// `deadline` (--max-seconds), when given, is asked at every step: a trace whose time is up
// throws TimeLimitReached.
TraceResult traceGeodesic(const SurfaceMesh& mesh, SurfacePoint start, Vec3 dir, double length,
                          Deadline* deadline = nullptr);

// With a field: the (hyper)streamline leaving `start` at oriented angle `angle` (radians,
// counter-clockwise about the surface normal) to the field, i.e. whose tangent is the
// field direction turned by `angle` everywhere. For a line field the sign of the field
// direction is taken continuous along the curve and, at the start, such that the curve
// leaves on `initialDir`'s side (the caller passes the direction it wants to go in; a
// vector field's own sign decides and initialDir is not used). Entering a face with a
// wedge or trisector of the field, a curve that comes within the jump radius of it jumps
// across it (p' = 2d - p) and leaves with the negative (wedge) or the same (trisector)
// oriented angle to the jump as it came in with; the jump counts as arc length. From
// there on the curve keeps its new angle to the field: it is the streamline that carries
// the pattern through the singularity (the paper's "new tracing direction"), so after a
// jump the angle between `fieldDirection` and `direction` is no longer `angle`. A vector
// field's streamline stops at a zero of the field (stopped = true), as at the boundary.
TraceResult traceField(const SurfaceMesh& mesh, const DirectionField& field, SurfacePoint start,
                       Vec3 initialDir, double angle, double length, Deadline* deadline = nullptr);

// The oriented angle from a to b about the unit normal n, in (-pi, pi] (both taken in the
// plane orthogonal to n; 0 when either has no part there).
double orientedAngle(const Vec3& a, const Vec3& b, const Vec3& n);
// v turned by `angle` (radians, counter-clockwise seen from the tip of unit n) about n.
Vec3 rotateAbout(const Vec3& v, const Vec3& n, double angle);

}  // namespace fgsg::rt::field
