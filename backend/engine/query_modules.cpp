// The turtle's answers to the query modules of a parallel derivation's string
// (query_modules.h): the turtle reads the string as interpretString does, drawing
// nothing, and writes its position or one of its axes into each query module's
// arguments — x, y and, for three arguments, z, in the world's axes; ?E's, the first
// field's value where the turtle stands.
#include "backend/engine/derivation.h"
#include "backend/engine/query_modules.h"

#include <algorithm>

namespace fgsg::backend {

void Derivation::answerQueries(ModuleString& str) {
  if (!plan_.hasQuery) return;
  State st;
  st.width = m_.turtle.width;
  st.stackBase = stack_.size();
  const TurtleCommands::NotDrawing quiet(turtle_);
  for (const StringModule& mod : str.modules) {
    const StringOp& so = plan_[mod.op];
    double* a = str.args.data() + mod.firstArg;
    switch (so.kind) {
      case ir::OpKind::Emit:
        if (so.query == static_cast<int8_t>(QueryModule::Environment)) {
          if (!environment_)  // the front end asks for a field (E066); defensive
            throw DeriveError{so.op->loc, "R016", "the environmental query ?E needs a surface with a field"};
          environment_->environmentQuery(st.scope.P, a, so.argCount, so.op->loc);
        } else if (so.query >= 0) {
          rt::Vec3 v = st.scope.P;
          switch (static_cast<QueryModule>(so.query)) {
            case QueryModule::Heading: v = st.scope.Y(); break;
            case QueryModule::Up: v = st.scope.Z(); break;
            case QueryModule::Left: v = -st.scope.X(); break;
            default: break;
          }
          for (uint32_t k = 0; k < std::min<uint32_t>(so.argCount, 3); ++k) a[k] = v[k];
        } else if (so.draws >= 0) {
          turtle_.command(st, static_cast<ir::TurtleOp>(so.draws), a, std::min<uint32_t>(so.argCount, 1), so.op->loc);
        }
        break;
      case ir::OpKind::Turtle: turtle_.command(st, *so.op, a, so.argCount); break;
      case ir::OpKind::Instance: break;  // places, does not move the turtle
      default: scope_.command(st, *so.op, a); break;
    }
  }
  stack_.erase(stack_.begin() + static_cast<std::ptrdiff_t>(st.stackBase), stack_.end());
}

}  // namespace fgsg::backend
