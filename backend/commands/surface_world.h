// The environment of a field-guided grammar (FGSG §4): the surface it grows on and the
// fields declared on it. Scopes stand on surface points; T traces along the first
// field (or a straightest geodesic without one), RS turns about the surface normal,
// and field queries read the fields at the scope's surface point.
#pragma once

#include "backend/interp/eval.h"
#include "ir/ir.h"
#include "runtime/deadline.h"
#include "runtime/derivation.h"
#include "runtime/mesh.h"
#include "runtime/scope.h"

#include <memory>

namespace fgsg::rt::field {
class TangentField;
}
namespace fgsg::rt::surface {
struct SurfaceMesh;
}
#include <string>
#include <utility>
#include <vector>

namespace fgsg::backend {

class SurfaceGeometry;

class SurfaceWorld {
 public:
  // Builds the module's surface (or --surface's) and its fields. Files are looked up in
  // `searchDirs` (the grammar's folder first). Throws DeriveError at the declaration.
  // `deadline` (--max-seconds) bounds field design and smoothing (an expired one is R021
  // at the field). Once built, the world is only read: the const members may be called
  // from several threads (the plants of independent seeds grow concurrently).
  SurfaceWorld(const ir::Module& m, const rt::DeriveOptions& options,
               const std::vector<std::string>& searchDirs, rt::Deadline* deadline = nullptr);
  // The same on a geometry built already (fgsg view's SurfaceGeometryCache): only the
  // fields are built.
  SurfaceWorld(const ir::Module& m, const rt::DeriveOptions& options, const std::vector<std::string>& searchDirs,
               std::shared_ptr<const SurfaceGeometry> geometry, rt::Deadline* deadline = nullptr);
  ~SurfaceWorld();

  // Where the axiom starts: on the surface point closest to --start (default: to the
  // centre of the surface's bounding box), Z along the normal, X along the first field
  // (without one: the world X axis laid into the tangent plane).
  rt::Scope startScope() const;
  // A seed's start (--seed-points): on the surface point closest to `point`, X along
  // `direction` laid into the tangent plane (null: as startScope() chooses).
  rt::Scope startScopeAt(const rt::Vec3& point, const rt::Vec3* direction) const;
  // Puts `s` on surface point (face, bary) with X along `x` laid into the tangent plane,
  // Z the normal, keeping its lift (the destination of a march).
  void placeOn(rt::Scope& s, int face, const rt::Vec3& bary, const rt::Vec3& x) const;
  // The surface itself, in world space (after --surface-size).
  const rt::surface::SurfaceMesh& mesh() const;
  // T(tx, ty, tz): (tx, ty) traces along the surface, tz lifts along the normal. The
  // trace asks `deadline` (the calling derivation's --max-seconds; null: unbounded) and
  // throws rt::TimeLimitReached when it expires.
  void translate(rt::Scope& s, double tx, double ty, double tz, rt::Deadline* deadline) const;
  // RS(a): turns the scope about the surface normal at its point.
  void rotateAboutNormal(rt::Scope& s, double degrees) const;

  // F.member at the scope's surface point (members as in docs/language.md).
  double fieldNumber(const rt::Scope& s, uint32_t env, const std::string& member, ir::Loc at) const;
  rt::Vec3 fieldVector(const rt::Scope& s, uint32_t env, const std::string& member,
                       ir::Loc at) const;

  // An L-system's environmental query ?E (docs/language.md, the turtle): the first
  // declared field at the surface point closest to `point` — a scalar field's value in
  // out[0]; another field's world vector (a tensor's major eigenvector scaled by its
  // eigenvalue, as F.vector) in out[0..n). Without a field: R016 at `at`.
  void environmentQuery(const rt::Vec3& point, double* out, uint32_t n, ir::Loc at) const;

  // The distance along the surface between the scopes' surface points (`collision
  // geodesic R`), by fast marching over the triangles (Kimmel & Sethian) from the first
  // point's face to the second's; points in one face are measured straight. Stops at
  // `limit`, returning a value >= limit beyond it.
  double geodesicDistance(const rt::Scope& a, const rt::Scope& b, double limit) const;

  // The surface as output geometry (world space, smooth normals).
  rt::Mesh surfaceMesh() const;
  // The declared fields in declaration order, by name (`fgsg field` draws them).
  std::vector<std::pair<std::string, const rt::field::TangentField*>> fields() const;
  size_t faceCount() const;

 private:
  void buildFields(const ir::Module& m, const rt::DeriveOptions& options,
                   const std::vector<std::string>& searchDirs);
  const rt::field::TangentField& fieldAt(uint32_t env, ir::Loc at) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fgsg::backend
