// Smooth terminals (Buron et al. 2015, §6): every segment of the marching graph becomes a
// cubic Bezier curve from its start node to its end node, tangent to the surface at both
// ends and C1 — not only G1 — where segments meet, so the terminals bent along them
// (runtime/marching/curve_bend.h) join without a kink.
//
// At each node, one unit tangent t and one handle length h are shared by all its
// segments; a segment's inner control point next to the node is p + o h t with o = +1 or
// -1 its side of the node:
//  * t is the tangent-plane projection (I - n n^T) of the sum of the unit directions of
//    all segments at the node, each taken "through" the node (the paper's formula, which
//    for a plain polyline averages the incoming and outgoing directions). Where segments
//    come in and go out (a continuation, a branch point) each is taken in its direction
//    of growth: an incoming segment's direction points into the node, an outgoing one's
//    out of it, and every curve there has the same derivative 3 h t in the direction of
//    growth — B_in'(1) = B_out'(0) for every pair (a branch leaves along its parent).
//  * Where only outgoing segments meet (a seed that grew several ways) or only incoming
//    ones, no growth passes through, and "through" is chosen geometrically: each segment
//    is taken either leaving along +t or along -t, the split that makes the sum longest
//    (a local optimum of single flips, exact for two segments). Two branches growing
//    apart from a seed then form one smooth curve through it (C1 once one of them is
//    reversed: B_1'(0) = -B_2'(0)); two branches at an acute angle leave together.
//  * A sum that vanishes (a march turning straight back) falls back to the first
//    segment's own direction, projected; one perpendicular to the surface, to any
//    tangent direction.
//  * h is a third of the mean of the segments' projections |t . (q - p)| (the paper's
//    per-segment formula b1 = p + 1/3 t t^T (q - p), averaged so that all curves at the
//    node share it), at most a third of the shortest segment there: a segment's inner
//    control points then stay within a third of its length from their ends.
//
// Segments of zero length (both ends at one point) are left out of every node's
// tangent and handle; their curve is that point.
//
// Only C1 segments (MarchSegment::smoothness) share the nodes' tangents; the others are
// left out of them too and get a curve of their own (the paper's lesser smoothness
// settings, §6: "reducing the smoothness constraints is straightforward"):
//  * C0: each inner control point is its end plus a third of the chord b - a projected
//    onto that end's tangent plane, b1 = a + (I - na na^T)(b - a) / 3 and
//    b2 = b - (I - nb nb^T)(b - a) / 3 — the paper's b1 = p + 1/3 t t^T (q - p) with t the
//    segment's own direction: tangent to the surface, meeting its neighbours at the
//    nodes with a kink where the march turns;
//  * Discontinuous: the straight chord, b1 = a + (b - a) / 3, b2 = b - (b - a) / 3 (its
//    terminals are not bent: the march leaves them rigid). Normals are normalised (a zero normal
// leaves directions unprojected).
#pragma once

#include "runtime/instances.h"
#include "runtime/marching/march_graph.h"

#include <vector>

namespace fgsg::rt::marching {

// One curve per segment, in the segments' order: control[0] and control[3] are the
// segment's start and end node, normal0 and normal1 their unit normals. Throws
// std::out_of_range when a segment names a node that does not exist (a caller's bug).
std::vector<CurveSegment> smoothSegments(const std::vector<MarchNode>& nodes,
                                         const std::vector<MarchSegment>& segments);

}  // namespace fgsg::rt::marching
