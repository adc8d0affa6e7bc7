// Internal consistency of a module: the IR's invariants that every producer (lowering,
// folding) must keep and every consumer (interpreter, LLVM backend) relies on. A problem
// here is a compiler bug, not a user error, so the messages speak IR, not source.
#pragma once

#include <string>
#include <vector>

#include "ir/ir.h"

namespace fgsg::ir {

// Appends one line per broken invariant to `problems` ("rule 2 \"p1\" alt 0 op 3
// (emit): ..."); returns true when none was found.
bool verifyModule(const Module& m, std::vector<std::string>& problems);

}  // namespace fgsg::ir
