// The queries a rule may ask about its shape (QueryHost): Shape.visible, Shape.occlusion
// and the field queries, answered by the derivation's state.
#include "backend/engine/derivation.h"

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

double Derivation::texture(const rt::Scope& scope, uint32_t env, ir::Loc at) {
  return marching_.sampleTexture(scope, env, at);
}

}  // namespace fgsg::backend
