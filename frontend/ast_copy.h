#pragma once
// Copies of expression trees: the front end rewrites copies (CGA translation, inlining of
// imported functions) and keeps the parsed original intact.

#include "frontend/ast.h"

namespace fgsg::frontend {

// One expression node with every field but its arguments: callers that substitute while
// copying (parameters -> arguments) recurse themselves.
inline ExprPtr copyExprNode(const Expr& from) {
  auto c = std::make_unique<Expr>();
  c->kind = from.kind;
  c->range = from.range;
  c->number = from.number;
  c->boolean = from.boolean;
  c->text = from.text;
  c->object = from.object;
  c->hasCall = from.hasCall;
  return c;
}

// A deep copy of the whole tree.
inline ExprPtr cloneExpr(const Expr& from) {
  ExprPtr c = copyExprNode(from);
  for (const ExprPtr& a : from.args) c->args.push_back(a ? cloneExpr(*a) : nullptr);
  return c;
}

}  // namespace fgsg::frontend
