// The queries a rule may ask about its shape (QueryHost): Shape.visible, Shape.occlusion
// and the field queries, answered by the derivation's state.
#include "backend/engine/derivation.h"
#include "runtime/cga/geometry_queries.h"

#include <array>
#include <cmath>

namespace fgsg::backend {

double Derivation::visible(const rt::Scope& scope, const std::string& target, ir::Loc at) {
  if (target != "street")
    throw DeriveError{at, "R011",
                      "Shape.visible(\"" + target + "\"): the only target is \"street\""};
  // The street lies in front of the lot: the axiom's +Z side. A face sees it when its
  // outward normal points within 60 degrees of that direction.
  return scope.Z().dot(streetDirection_) > 0.5 ? 1.0 : 0.0;
}

double Derivation::occlusion(const rt::Scope& scope, ir::Loc) {
  switch (occluders_.test(scope)) {
    case rt::Occlusion::None: return noneId_;
    case rt::Occlusion::Partial: return partId_;
    case rt::Occlusion::Full: return fullId_;
  }
  return noneId_;
}

// Fields live on surfaces: the compiler refuses a field without one.
double Derivation::fieldNumber(const rt::Scope& scope, uint32_t env, const std::string& member,
                               ir::Loc at) {
  if (!surface_) throw DeriveError{at, "R016", "field queries need a surface"};
  return surface_->fieldNumber(scope, env, member, at);
}

rt::Vec3 Derivation::fieldVector(const rt::Scope& scope, uint32_t env, const std::string& member,
                                 ir::Loc at) {
  if (!surface_) throw DeriveError{at, "R016", "field queries need a surface"};
  return surface_->fieldVector(scope, env, member, at);
}

// Geometry.area ... (CGA's geometry.*()) of the shape's own geometry.
double Derivation::geometry(ir::Query q, const rt::Scope& scope, const rt::GeomRef& geom, double arg, ir::Loc at) {
  if (q == ir::Query::GeometryIsPlanar) {
    if (!std::isfinite(arg) || arg < 0)
      throw DeriveError{at, "R011", "Geometry.isPlanar: the tolerance must be an angle of 0 degrees or more"};
    return rt::cga::geometryIsPlanar(scope, geom, arena_, arg) ? 1.0 : 0.0;
  }
  if (q == ir::Query::GeometryDu || q == ir::Query::GeometryDv) {
    // Without a projection (setupProjection, texture), or after deleteUV, the geometry has
    // no texture coordinates in that uv set (arg: the set, the query's extra).
    const rt::cga::UvProjection* projection = textures_.projection(scope.projection, uint32_t(arg));
    if (!projection || !projection->coordinates) return 0.0;
    const std::array<double, 2> spread = rt::cga::geometryUvSpread(scope, geom, arena_, *projection);
    return spread[q == ir::Query::GeometryDu ? 0 : 1];
  }
  if (q == ir::Query::GeometryAngle)  // arg: the selector, the query's extra
    return rt::cga::geometryAngle(scope, geom, arena_, static_cast<rt::cga::GeometryAngleKind>(static_cast<int>(arg)));
  const rt::cga::GeometryFacts g = rt::cga::geometryFacts(scope, geom, arena_);
  switch (q) {
    case ir::Query::GeometryArea: return g.area;
    case ir::Query::GeometryHeight: return g.height;
    case ir::Query::GeometryVertices: return g.vertices;
    case ir::Query::GeometryFaces: return g.faces;
    case ir::Query::GeometryIsConcave: return g.concave ? 1.0 : 0.0;
    case ir::Query::GeometryBoundaryLength: return g.boundaryLength;
    default: break;
  }
  throw DeriveError{at, "R900", "internal: unknown geometry query"};
}

double Derivation::texture(const rt::Scope& scope, uint32_t env, ir::Loc at) {
  return marching_.sampleTexture(scope, env, at);
}

}  // namespace fgsg::backend
