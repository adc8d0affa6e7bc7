// The textual form of the IR: what `fgsg ir FILE` prints and golden tests compare.
// Line-oriented and deterministic (no addresses, no source locations); parameters,
// attributes, symbols and strings appear by name. Out-of-range indices print as
// `sym#7`, `attr#3`, `@5` rather than crashing, so a corrupt module can be inspected.
#pragma once

#include <string>

#include "ir/ir.h"

namespace fgsg::ir {

std::string printModule(const Module& m);
std::string printRule(const Module& m, const Rule& rule);
// `rule` resolves parameter slots to names; null outside a rule (axiom, attributes).
std::string printExpr(const Module& m, const Rule* rule, const Expr& e);
// Shortest text that reads back as exactly `v` ("0.6", "1e-09", "12").
std::string printNumber(double v);

}  // namespace fgsg::ir
