// Bending a smooth terminal along its curve (Buron et al. 2015, §6): an instance placed
// rigidly on a marching segment (its unit box's X axis along the segment's straight chord
// from control[0] to control[3]) is deformed so that its X axis follows the curve B and
// its cross-sections turn with the curve's frame (runtime/marching/curve_frame.h).
//
// A rigid world point q (the asset point p through the instance transform M) goes to
//     B(s) + R(s) (q - chord(s)),
// where s is q's position along the chord (its projection, as a fraction of the chord:
// s = x when M's X column is the chord), chord(s) = c0 + s (c3 - c0) the point of the
// chord there, and R(s) the rotation taking the straight scope's frame onto the curve's:
//     (chord direction, scope side, scope up) -> (tangent, side, up) at s.
// The scope's up is M's Z column made orthogonal to the chord (its Y column's cross
// when Z is flat), as on a surface scope, whose Z is the normal: the scope's roll about
// its chord is replaced by the surface's, so two terminals of the same cross-section
// meet ring for ring where their segments meet, whatever their scopes' rolls. On a
// straight segment whose handles are a third of its length, with the scope's Z along the
// (constant) normal, the bend is the identity. Beyond the chord's ends (s < 0, s > 1)
// the curve continues along its end tangent and the end frame holds. Normals turn by
// R(s) — exact for a rigid motion, the usual approximation for a bend.
//
// A curve whose chord has no length bends nothing: points stay where M puts them.
//
// Sharing along rings: B(s), chord(s) and R(s) — a BendSection — depend on s alone, so
// the points with the same s can share one. at() computes an asset point's s as an affine
// function of it, s = a . local + b, in which a column of M (nearly) perpendicular to the
// chord — |cosine| below 1e-12, as a scope's Y and Z are to its X up to rounding —
// contributes nothing. So the vertices of a ring across the asset's X axis (the same
// local x, as on the bark tube) get exactly the same s, and evaluating the section once
// per distinct s gives at()'s bytes. Leaving such a column out moves s by rounding only.
#pragma once

#include "runtime/instances.h"
#include "runtime/scope.h"

#include <array>

namespace fgsg::rt::marching {

// Where a bent asset point lands and how its normals turn there.
struct BentPoint {
  Vec3 position;
  Mat3 rotation;  // applies to the rigidly transformed normal
};

// The part of the bend that all points with the same s share.
struct BendSection {
  double s = 0;
  Vec3 onCurve = Vec3::Zero();       // B(s); beyond an end, along the end tangent
  Vec3 chordPoint = Vec3::Zero();    // chord(s)
  Mat3 rotation = Mat3::Identity();  // R(s)
};

class CurveBend {
 public:
  // `unitBoxToWorld`: the instance's rigid placement, column-major (Instance::transform).
  CurveBend(const CurveSegment& curve, const std::array<double, 16>& unitBoxToWorld);

  // The bent image of `local`, a point of the asset's unit box:
  // place(section(along(local)), M local).
  BentPoint at(const Vec3& local) const;
  // The same for a point already placed rigidly in the world (M local), its s projected
  // from the world point (equal to at()'s up to rounding).
  BentPoint atRigid(const Vec3& rigid) const;

  // at() in steps, for sharing sections (see above): s of the asset point `local`, the
  // section at s, and the bent image of `rigid` (M local) given its section.
  double along(const Vec3& local) const { return along_.dot(local) + alongAt0_; }
  BendSection section(double s) const;
  BentPoint place(const BendSection& section, const Vec3& rigid) const {
    if (length_ == 0) return {rigid, Mat3::Identity()};
    return {section.onCurve + section.rotation * (rigid - section.chordPoint), section.rotation};
  }
  // False when the chord has no length and points stay rigid.
  bool bends() const { return length_ > 0; }

  // For placing many points of one section at once (assembling a terminal): the asset
  // points with along(local) == s go to linear * local + offset (place(section(s), M local)
  // up to rounding), and a rigidly placed normal n turns to frame * (scopeFrame()^T n).
  // R(s) = frame scopeFrame()^T, so the scope frame's part is applied once per instance.
  struct SectionMap {
    Mat3 linear;
    Vec3 offset;
    Mat3 frame;  // the curve's (tangent, side, up) at s
  };
  SectionMap sectionMap(double s) const;
  const Mat3& scopeFrame() const { return scopeFrame_; }

 private:
  CurveSegment curve_;
  Mat4 placement_;
  Vec3 start_, chord_;      // c0 and c3 - c0
  double length_ = 0;       // |c3 - c0|, 0: no bend
  Mat3 scopeFrame_;         // columns: chord direction, scope side, scope up
  Vec3 along_ = Vec3::Zero();  // s = along_ . local + alongAt0_
  double alongAt0_ = 0;
  // In the scope frame (scopeFrame_^T times): M's linear part, M's translation - c0, the
  // chord. R(s) (M local - chord(s)) = frame(s) (scopeLinear_ local + scopeOffset_ - s scopeChord_).
  Mat3 scopeLinear_ = Mat3::Identity();
  Vec3 scopeOffset_ = Vec3::Zero(), scopeChord_ = Vec3::Zero();

  // The curve's frame (tangent, side, up) and point at s, for section() and sectionMap().
  void curveAt(double s, Mat3& frame, Vec3& onCurve) const;
};

// One-off convenience: the bent world position of the unit-box point `local`.
Vec3 bendAlongCurve(const CurveSegment& curve, const std::array<double, 16>& unitBoxToWorld, const Vec3& local);

}  // namespace fgsg::rt::marching
