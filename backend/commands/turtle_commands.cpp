#include "backend/commands/turtle_commands.h"

#include "backend/engine/derivation.h"

namespace fgsg::backend {

void TurtleCommands::command(State& st, ir::TurtleOp op, const double* args, uint32_t n, ir::Loc loc) {
  using ir::TurtleOp;
  const ir::Module& m = d_.module();
  const double angle = n > 0 ? args[0] : m.turtle.angle;
  const double step = n > 0 ? args[0] : m.turtle.step;
  switch (op) {
    case TurtleOp::Forward: {
      // A segment is a cylinder of the turtle's width along the heading (scope Y).
      rt::Scope seg = st.scope;
      seg.P -= 0.5 * st.width * (st.scope.X() + st.scope.Z());
      seg.S = rt::Vec3(st.width, step, st.width);
      d_.placeInstance(d_.segmentAsset(), seg, d_.segmentSymbol(), nullptr, 0, loc);
      st.scope.P += step * st.scope.Y();
      break;
    }
    case TurtleOp::Move: st.scope.P += step * st.scope.Y(); break;
    case TurtleOp::Left: scope_.turn(st.scope, 2, angle); break;
    case TurtleOp::Right: scope_.turn(st.scope, 2, -angle); break;
    case TurtleOp::PitchDown: scope_.turn(st.scope, 0, angle); break;
    case TurtleOp::PitchUp: scope_.turn(st.scope, 0, -angle); break;
    case TurtleOp::RollLeft: scope_.turn(st.scope, 1, angle); break;
    case TurtleOp::RollRight: scope_.turn(st.scope, 1, -angle); break;
    case TurtleOp::TurnAround: scope_.turn(st.scope, 2, 180.0); break;
    case TurtleOp::Width:
      if (n > 0) st.width = args[0];
      break;
  }
}

void TurtleCommands::drawSymbol(const ir::Symbol& sym, const rt::Scope& scope, const double* params) {
  if (sym.name != "F") return;
  State st;
  st.scope = scope;
  st.width = d_.module().turtle.width;
  command(st, ir::TurtleOp::Forward, params, sym.slotCount > 0 ? 1 : 0, {});
}

}  // namespace fgsg::backend
