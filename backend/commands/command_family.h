// The one interface between the engine core (backend/engine/) and what a command does.
// A family owns the ops of one concept (scope commands, the turtle, CGA splits, ...);
// the core dispatches every op it does not handle itself (Emit) to the family that
// registered its kind, with the arguments already evaluated in IR order (op.args, then
// each op.sizes[k].value) — the same layout compiled code passes to fgsg_rt_op.
#pragma once

#include "backend/engine/successor.h"
#include "backend/interp/eval.h"
#include "ir/ir.h"

#include <cstdint>
#include <vector>

namespace fgsg::backend {

class CommandFamily {
 public:
  virtual ~CommandFamily() = default;
  // The op kinds this family applies (asked once, when the engine is built).
  virtual std::vector<ir::OpKind> kinds() const = 0;
  // Applies one op to the running successor: its scope and stack (st), what it knows
  // about itself (ex: set ex.culled to drop the rest of the production) and the frame
  // its bodies evaluate in (f).
  virtual void apply(const ir::Op& op, const double* args, uint32_t n, State& st, Exec& ex, Frame& f) = 0;
};

}  // namespace fgsg::backend
