// Which queries a grammar asks: the one walk over its expressions (guards, probabilities,
// op arguments and sizes, nested bodies, the axiom) that the derivation's facts about the
// grammar share (a scope occlusion query, a texture query, any context query).
#pragma once

#include "ir/ir.h"

#include <functional>

namespace fgsg::ir {

// Whether any query the grammar asks, at any depth of an expression, satisfies `pred`.
bool anyQuery(const Module& m, const std::function<bool(Query)>& pred);

}  // namespace fgsg::ir
