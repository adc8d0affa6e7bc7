// The turtle (ABOP): F and f draw and move along the heading (scope Y), + - & ^ \ / |
// turn, ! sets the width. A segment is a cylinder instance of the turtle's width (or what
// `turtle segments` says). { . } are ABOP's polygons (ch. 5): `{` starts collecting
// vertices, `.` adds the turtle's position, `}` fills them; polygons nest, and are
// independent of [ ] (the cordate leaf `[+A{.].C.}` collects across branches).
#pragma once

#include "backend/commands/command_family.h"
#include "backend/commands/generalized_cylinder.h"
#include "backend/commands/scope_commands.h"
#include "runtime/derivation.h"

#include <vector>

namespace fgsg::backend {

class Derivation;

class TurtleCommands final : public CommandFamily {
 public:
  TurtleCommands(Derivation& derivation, ScopeCommands& scope) : d_(derivation), scope_(scope) {}

  std::vector<ir::OpKind> kinds() const override { return {ir::OpKind::Turtle}; }
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec&, Frame&) override {
    command(st, op, a, n);
  }

  // While one lives, the turtle moves and turns but places nothing: segments, spheres,
  // circles and polygons are left out (the query modules' pass, query_modules.cpp).
  class NotDrawing {
   public:
    explicit NotDrawing(TurtleCommands& t) : t_(t) { t_.drawing_ = false; }
    ~NotDrawing() { t_.drawing_ = true; }
    NotDrawing(const NotDrawing&) = delete;
    NotDrawing& operator=(const NotDrawing&) = delete;

   private:
    TurtleCommands& t_;
  };

  // The turtle op `op` (a Turtle op) with its evaluated arguments.
  void command(State& st, const ir::Op& op, const double* args, uint32_t n) {
    if (op.index == static_cast<uint32_t>(ir::TurtleOp::SurfaceBox)) return surfaceBox(st, op.asset, args, n);
    if (op.index == static_cast<uint32_t>(ir::TurtleOp::Sphere)) return sphere(st, op.asset, args, n, op.loc);
    if (op.index == static_cast<uint32_t>(ir::TurtleOp::Circle)) return circle(st, op.asset, args, n, op.loc);
    if (op.index >= static_cast<uint32_t>(ir::TurtleOp::CylinderStart))
      return cylinderCommand(st, static_cast<ir::TurtleOp>(op.index), args, n, op.loc);
    command(st, static_cast<ir::TurtleOp>(op.index), args, n, op.loc);
  }

  // One turtle command; without an argument the grammar's default angle or step.
  void command(State& st, ir::TurtleOp op, const double* args, uint32_t n, ir::Loc loc);

  // F is a shape symbol when rules rewrite it; where none applies it still draws like the
  // turtle command, as after a parallel derivation. Length: its first parameter, else
  // the turtle step.
  void drawSymbol(const ir::Symbol& sym, const rt::Scope& scope, const double* params);

  // R032 for each generalized cylinder started and never ended (not drawn); forgets them.
  void endCylinders(std::vector<rt::DeriveMessage>& messages);

 private:
  static void rollHorizontal(rt::Scope& scope);
  static void bend(rt::Scope& scope, const Tropism& tropism);
  void surfaceBox(State& st, uint32_t asset, const double* args, uint32_t n);
  void sphere(const State& st, uint32_t asset, const double* args, uint32_t n, ir::Loc loc);
  void circle(const State& st, uint32_t asset, const double* args, uint32_t n, ir::Loc loc);
  void colorIndex(State& st, double i, ir::Loc loc) const;
  static void setHeading(State& st, const double* args, ir::Loc loc);
  // lpfg's @Gs, @Gc(n), @Ge(n) and L-Py's @Gc, @Ge (generalized_cylinder.h).
  struct OpenCylinder {
    std::vector<CylinderControlPoint> points;
    rt::Vec3 up;          // the turtle's U at the start: where the rings' first vertex lies
    size_t depth = 0;     // the [ ] depth it was started at: a branch inside does not continue it
    bool lpy = false;     // started by L-Py's @Gc: each F adds a control point
    bool open = true;
    ir::Loc start;
  };
  void cylinderCommand(State& st, ir::TurtleOp op, const double* args, uint32_t n, ir::Loc loc);
  // The cylinder open in this branch (not in an enclosing one), or nullptr.
  OpenCylinder* openCylinder(const State& st);
  CylinderControlPoint controlPoint(const State& st, const double* args, uint32_t n, ir::Loc loc) const;

  Derivation& d_;
  ScopeCommands& scope_;
  std::vector<std::vector<rt::Vec3>> polygons_;  // open polygons, innermost last
  bool drawing_ = true;                          // false while a NotDrawing lives
  std::vector<OpenCylinder> cylinders_;          // State::cylinder indexes them
};

}  // namespace fgsg::backend
