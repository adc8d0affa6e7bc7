// Constant folding over every expression of a module (guards, probabilities, op
// arguments, sizes, nested bodies, the axiom). Folds operators, selects and builtins on
// constants and a few IEEE-exact identities (x*1, x/1, x-0, x+(-0), --x, !!x).
// Never folds Rand (it advances the shape's random stream), queries, or attributes
// (they can be set from outside); never produces inf or NaN, so a division by a
// constant zero stays in the IR for sema to report.
#pragma once

#include "ir/ir.h"

namespace fgsg::ir {

// Returns the number of rewrites; the module is valid before => valid after.
int foldConstants(Module& m);

}  // namespace fgsg::ir
