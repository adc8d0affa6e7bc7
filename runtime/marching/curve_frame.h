// Points and frames along a smooth terminal's curve (runtime/instances.h CurveSegment):
// the cubic Bezier B(x), x in [0, 1], with its control points, and the frame a terminal
// bent along it follows (Buron et al. 2015, §6: "a local frame along the curve").
#pragma once

#include "runtime/instances.h"
#include "runtime/scope.h"

namespace fgsg::rt::marching {

Vec3 controlPoint(const CurveSegment& curve, int index);

// B(x) = (1-x)^3 c0 + 3 (1-x)^2 x c1 + 3 (1-x) x^2 c2 + x^3 c3; B(0) = c0 and B(1) = c3
// exactly.
Vec3 bezierPoint(const CurveSegment& curve, double x);
// dB/dx = 3 ((1-x)^2 (c1-c0) + 2 (1-x) x (c2-c1) + x^2 (c3-c2)).
Vec3 bezierDerivative(const CurveSegment& curve, double x);

// The frame at B(x). (tangent, side, up) is right-handed and orthonormal — the axes
// (X, Y, Z) of a scope standing on a surface (X along the march, Z along the normal,
// Y = Z x X), so a terminal's scope maps onto it without a mirror:
//  * tangent: B'(x) normalised (the chord's direction where B' vanishes);
//  * up: the end normals interpolated, (1-x) normal0 + x normal1, made orthogonal to the
//    tangent and normalised (where that vanishes: normal0, then normal1, then any
//    direction across the tangent);
//  * side = up x tangent.
// Everything at x = 0 depends only on c0, c1 and normal0, at x = 1 only on c2, c3 and
// normal1: curves that share a node (and its tangent, handle and normal) share the frame
// there, up to rounding.
struct CurveFrame {
  Vec3 point, tangent, up, side;
};

CurveFrame curveFrame(const CurveSegment& curve, double x);

}  // namespace fgsg::rt::marching
