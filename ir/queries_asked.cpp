#include "ir/queries_asked.h"

namespace fgsg::ir {

bool anyQuery(const Module& m, const std::function<bool(Query)>& pred) {
  const std::function<bool(const Expr&)> inExpr = [&](const Expr& e) {
    if (e.op == ExprOp::Query && pred(static_cast<Query>(e.index))) return true;
    for (const Expr& a : e.args)
      if (inExpr(a)) return true;
    return false;
  };
  for (const Rule& r : m.rules) {
    if (r.hasGuard && inExpr(r.guard)) return true;
    for (const Alternative& alt : r.alternatives)
      if (inExpr(alt.probability)) return true;
  }
  // The ops of every rule and of the axiom, bodies included.
  return anyOp(m, [&](const Op& op) {
    for (const Expr& a : op.args)
      if (inExpr(a)) return true;
    for (const auto& size : op.sizes)
      if (inExpr(size.value)) return true;
    return false;
  });
}

}  // namespace fgsg::ir
