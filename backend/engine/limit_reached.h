// How a derivation ends early when a limit (--max-shapes, --max-seconds, --max-memory)
// is reached: thrown up to Derivation::run, which keeps what was derived with an R004
// warning.
#pragma once

#include "ir/ir.h"

#include <string>

namespace fgsg::backend {

struct LimitReached {
  std::string message;
  ir::Loc loc;
};

}  // namespace fgsg::backend
