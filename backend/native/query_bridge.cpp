#include "backend/native/query_bridge.h"

namespace fgsg::backend::native {

int32_t QueryBridge::answer(void* user, uint32_t kind, uint32_t env, uint32_t extra,
                            const double* args, uint32_t nargs, int32_t line, int32_t col,
                            double* out) noexcept {
  auto& self = *static_cast<QueryBridge*>(user);
  const Frame& f = self.frame_;
  const auto q = static_cast<ir::Query>(kind);
  const ir::Loc at{line, col};
  const bool needsScope = q != ir::Query::ShapeDepth && q != ir::Query::ShapeIndex && q != ir::Query::Feature;
  if (needsScope && !f.scope) return FGSG_E_NO_SCOPE;
  try {
    if (ir::isContextQuery(q)) {
      if (nargs < 1) return FGSG_E_INTERNAL;
      *out = f.host->context(q, extra, self.m_.strings.at(static_cast<size_t>(args[0])), *f.scope,
                             f.geom ? *f.geom : rt::GeomRef{}, at);
      return FGSG_OK;
    }
    if (ir::isGeometryQuery(q)) {
      if (q == ir::Query::GeometryIsPlanar && nargs < 1) return FGSG_E_INTERNAL;
      *out = f.host->geometry(q, *f.scope, f.geom ? *f.geom : rt::GeomRef{},
                              q == ir::Query::GeometryIsPlanar ? args[0]
                              : q == ir::Query::GeometryAngle || q == ir::Query::GeometryDu || q == ir::Query::GeometryDv
                                  ? double(extra)
                                  : 0.0,
                              at);
      return FGSG_OK;
    }
    switch (q) {
      case ir::Query::ScopeSx: *out = f.scope->S.x(); return FGSG_OK;
      case ir::Query::ScopeSy: *out = f.scope->S.y(); return FGSG_OK;
      case ir::Query::ScopeSz: *out = f.scope->S.z(); return FGSG_OK;
      case ir::Query::ScopePx: *out = f.scope->P.x(); return FGSG_OK;
      case ir::Query::ScopePy: *out = f.scope->P.y(); return FGSG_OK;
      case ir::Query::ScopePz: *out = f.scope->P.z(); return FGSG_OK;
      case ir::Query::ShapeDepth: *out = f.depth; return FGSG_OK;
      case ir::Query::ShapeIndex: *out = f.index; return FGSG_OK;
      case ir::Query::ShapeVisible:
        if (nargs < 1) return FGSG_E_INTERNAL;
        *out = f.host->visible(*f.scope, self.m_.strings.at(static_cast<size_t>(args[0])), at);
        return FGSG_OK;
      case ir::Query::ScopeOcc: *out = f.host->occlusion(*f.scope, at); return FGSG_OK;
      case ir::Query::Field:
        // With one argument: that component (0, 1, 2) of a vector member.
        *out = nargs == 1 ? f.host->fieldVector(*f.scope, env, self.m_.strings.at(extra), at)
                                [static_cast<int>(args[0])]
                          : f.host->fieldNumber(*f.scope, env, self.m_.strings.at(extra), at);
        return FGSG_OK;
      case ir::Query::Texture: *out = f.host->texture(*f.scope, env, at); return FGSG_OK;
      case ir::Query::Feature:
        *out = f.host->feature(self.m_.strings.at(extra),
                               nargs ? self.m_.strings.at(static_cast<size_t>(args[0])) : std::string(), at);
        return FGSG_OK;
      case ir::Query::ShapeSplitIndex: *out = f.scope->place.splitIndex; return FGSG_OK;
      case ir::Query::ShapeSplitTotal: *out = f.scope->place.splitTotal; return FGSG_OK;
      case ir::Query::ShapeCompIndex: *out = f.scope->place.compIndex; return FGSG_OK;
      case ir::Query::ShapeCompTotal: *out = f.scope->place.compTotal; return FGSG_OK;
      case ir::Query::ShapeCompSel: *out = compSelector(self.m_, f.scope->place, extra); return FGSG_OK;
      default: break;  // the geometry queries, above
    }
    return FGSG_E_INTERNAL;
  } catch (const DeriveError& e) {
    self.hostError_ = e;
  } catch (const std::exception& e) {
    self.hostError_ = DeriveError{at, "R900", std::string("internal: ") + e.what()};
  } catch (...) {
    self.hostError_ = DeriveError{at, "R900", "internal: the query host failed"};
  }
  return FGSG_E_HOST;
}

DeriveError QueryBridge::error(const FgsgContext& ctx) const {
  const ir::Loc at{ctx.errorLine, ctx.errorCol};
  switch (static_cast<FgsgErrorCode>(ctx.errorCode)) {
    case FGSG_OK:
    case FGSG_E_UNUSED_3:
    case FGSG_E_FIELD: break;
    case FGSG_E_VEC_UNAVAILABLE:
      return {at, "R900", "internal error: a vector expression the interpreter cannot read"};
    case FGSG_E_NO_SCOPE:
      return {at, "R006", "scope queries cannot be answered while a parallel derivation rewrites "
                          "its string: modules get their scope only when the turtle interprets it"};
    case FGSG_E_HOST:
      if (hostError_) return *hostError_;
      break;
    case FGSG_E_INTERNAL: return {at, "R900", "internal: an expression the JIT cannot evaluate"};
  }
  return {at, "R900", "internal: unknown JIT error " + std::to_string(ctx.errorCode)};
}

}  // namespace fgsg::backend::native
