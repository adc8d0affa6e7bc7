#include "backend/commands/turtle_commands.h"

#include "backend/engine/derivation.h"

#include <algorithm>
#include <cmath>

namespace fgsg::backend {

void TurtleCommands::command(State& st, ir::TurtleOp op, const double* args, uint32_t n, ir::Loc loc) {
  using ir::TurtleOp;
  const ir::Module& m = d_.module();
  const double angle = n > 0 ? args[0] : m.turtle.angle;
  const double step = n > 0 ? args[0] : m.turtle.step;
  switch (op) {
    case TurtleOp::Forward: {
      // Inside a generalized cylinder the tube is the drawing: no segment of its own.
      OpenCylinder* tube = st.cylinder < 0 ? nullptr : openCylinder(st);
      // A segment is a cylinder (or tube) of the turtle's width along the heading (scope
      // Y), centred on the path; a ribbon is the flat quad in the turtle's X-Y plane; a
      // line lies on the box's Y edge, the path itself.
      if (drawing_ && !tube) {
        rt::Scope seg = st.scope;
        switch (m.turtle.segments) {
          case ir::TurtleSegments::Ribbons: seg.P -= 0.5 * st.width * st.scope.X(); break;
          case ir::TurtleSegments::Lines: break;
          default: seg.P -= 0.5 * st.width * (st.scope.X() + st.scope.Z()); break;
        }
        seg.S = rt::Vec3(st.width, step, st.width);
        d_.placeInstance(d_.segmentAsset(), seg, d_.segmentSymbol(), nullptr, 0, loc);
      }
      st.scope.P += step * st.scope.Y();
      if (st.tropism.elasticity != 0) bend(st.scope, st.tropism);
      if (tube && tube->lpy) tube->points.push_back(controlPoint(st, nullptr, 0, loc));  // L-Py: each F a point
      break;
    }
    case TurtleOp::Move: st.scope.P += step * st.scope.Y(); break;
    // The turtle's frame is H = Y, L = -X, U = Z (H x L = U); each turn is a right-handed
    // rotation about one of them, with L-Py's and lpfg's signs: + about U (H towards L),
    // & about L (H towards -U), / about H (L towards U). About L is about X negated.
    case TurtleOp::Left: scope_.turn(st.scope, 2, angle); break;
    case TurtleOp::Right: scope_.turn(st.scope, 2, -angle); break;
    case TurtleOp::PitchDown: scope_.turn(st.scope, 0, -angle); break;
    case TurtleOp::PitchUp: scope_.turn(st.scope, 0, angle); break;
    case TurtleOp::RollLeft: scope_.turn(st.scope, 1, -angle); break;
    case TurtleOp::RollRight: scope_.turn(st.scope, 1, angle); break;
    case TurtleOp::TurnAround: scope_.turn(st.scope, 2, 180.0); break;
    case TurtleOp::Width:
      if (n > 0) st.width = args[0];
      break;
    case TurtleOp::RollHorizontal: rollHorizontal(st.scope); break;
    case TurtleOp::PolygonBegin:
      if (drawing_) polygons_.emplace_back();
      break;
    case TurtleOp::PolygonVertex:
      if (drawing_ && !polygons_.empty()) polygons_.back().push_back(st.scope.P);  // outside a polygon: nothing
      break;
    case TurtleOp::PolygonEnd:
      if (!drawing_ || polygons_.empty()) break;  // a `}` with no `{`: nothing to fill
      d_.placePolygon(polygons_.back(), st.scope, loc);
      polygons_.pop_back();
      break;
    // ABOP's ' (lpfg's ;): the next colour of the palette, or '(i) colour i; lpfg's `,`
    // the previous one (not below 0, the default colours).
    case TurtleOp::ColorIndex: colorIndex(st, n > 0 ? args[0] : double(st.scope.colorIndex) + 1, loc); break;
    case TurtleOp::ColorPrevious:
      colorIndex(st, n > 0 ? args[0] : std::max(double(st.scope.colorIndex) - 1, 0.0), loc);
      break;
    case TurtleOp::Circle: break;  // only reached through the Op (its asset)
    case TurtleOp::CylinderStart:
    case TurtleOp::CylinderPoint:
    case TurtleOp::CylinderEnd: cylinderCommand(st, op, args, n, loc); break;
    case TurtleOp::SurfaceBox: surfaceBox(st, 0, args, n); break;  // only reached through the Op
    case TurtleOp::Tropism: {
      const rt::Vec3 t(args[0], args[1], args[2]);
      if (!(t.norm() > 0 && t.allFinite()))
        throw DeriveError{loc, "R027", "the tropism vector of @Tp must be finite and not zero"};
      st.tropism.direction = t.normalized();
      break;
    }
    case TurtleOp::Sphere: break;  // only reached through the Op (its asset)
    case TurtleOp::MoveTo: {
      const rt::Vec3 p(args[0], args[1], args[2]);
      if (!p.allFinite()) throw DeriveError{loc, "R027", "the point of @M must be finite"};
      st.scope.P = p;
      break;
    }
    case TurtleOp::SetHeading: setHeading(st, args, loc); break;
    case TurtleOp::Elasticity:
      if (!std::isfinite(args[0])) throw DeriveError{loc, "R027", "the elasticity of @Ts must be a finite number"};
      st.tropism.elasticity = args[0];
      break;
    case TurtleOp::Cut:
      // A parallel derivation cuts its string after each step (cutBranches); a successor
      // of a sequential one has no rest of a branch in a string to cut.
      throw DeriveError{loc, "R009",
                        "'%' cuts the rest of a branch from a parallel derivation's string "
                        "(`derive parallel N;`); a sequential derivation has no such string"};
  }
}

// ABOP's predefined surface `~leaf(s)`: the scope becomes the box the I() after it fills,
// standing on the turtle along the heading (Y from the turtle's position), `s` (default
// 1) along each axis or (sx, sy, sz), centred on the heading in X and Z. An asset flat
// along X or Z (`leaf`, `quad`, `disc` lie at z = 0 of their box) is not moved along
// that axis, so its plane passes through the turtle.
void TurtleCommands::surfaceBox(State& st, uint32_t asset, const double* args, uint32_t n) {
  const rt::Vec3 size = n == 3 ? rt::Vec3(args[0], args[1], args[2]) : rt::Vec3::Constant(n > 0 ? args[0] : 1.0);
  const uint8_t flat = d_.assetFlatAxes(asset);
  if (!(flat & 1)) st.scope.P -= 0.5 * size.x() * st.scope.X();
  if (!(flat & 4)) st.scope.P -= 0.5 * size.z() * st.scope.Z();
  st.scope.S = size;
}

// ABOP's $ (§2.2, Fig. 2.6): roll about the heading H (scope Y) until the left vector L
// (scope -X) is level, by the book's formula L = V x H / |V x H| with V the world's up
// (+Y), then U = H x L (scope Z), as L-Py's and lpfg's RollToVert. Heading straight up or
// down, no direction is level: the turtle stays as it is.
void TurtleCommands::rollHorizontal(rt::Scope& scope) {
  const rt::Vec3 heading = scope.Y();
  rt::Vec3 left = rt::Vec3::UnitY().cross(heading);
  if (!(left.norm() > 1e-12)) return;
  left.normalize();
  scope.axes.col(0) = -left;
  scope.axes.col(2) = heading.cross(left);
}

// lpfg's and L-Py's @O(r): a sphere of radius r (default half the turtle's width, as
// lpfg's), centred on the turtle, in the turtle's frame; the turtle does not move. It is
// turtle geometry, recorded under F as segments are.
void TurtleCommands::sphere(const State& st, uint32_t asset, const double* args, uint32_t n, ir::Loc loc) {
  if (!drawing_) return;
  const double r = n > 0 ? args[0] : 0.5 * st.width;
  if (!(r >= 0 && std::isfinite(r)))
    throw DeriveError{loc, "R027", "the radius of @O must be a finite number from 0, not " + std::to_string(r)};
  rt::Scope box = st.scope;
  box.P -= r * (st.scope.X() + st.scope.Y() + st.scope.Z());
  box.S = rt::Vec3::Constant(2 * r);
  d_.placeInstance(asset, box, d_.segmentSymbol(), nullptr, 0, loc);
}

// Colour i of the palette (i >= 1), or 0: the default colours. Saved and restored by
// [ ] with the scope.
void TurtleCommands::colorIndex(State& st, double i, ir::Loc loc) const {
  if (!(i >= 0 && i < 1e9 && i == std::floor(i)))
    throw DeriveError{loc, "R027", "a colour index must be a whole number from 0, not " + std::to_string(i)};
  st.scope.colorIndex = int32_t(i);
  st.scope.colored = st.scope.colorIndex > 0;
  if (st.scope.colored) {
    const auto& colors = d_.module().turtle.colors;
    st.scope.color = colors[size_t(st.scope.colorIndex - 1) % colors.size()];
  }
}

// lpfg's and L-Py's @o(r): a circle (the built-in `disc`) of radius r (default half the
// width), centred on the turtle, across the heading — in the plane of L and U, as
// PlantGL's turtle draws its disc; the turtle does not move. Recorded under F as
// segments are.
void TurtleCommands::circle(const State& st, uint32_t asset, const double* args, uint32_t n, ir::Loc loc) {
  if (!drawing_) return;
  const double r = n > 0 ? args[0] : 0.5 * st.width;
  if (!(r >= 0 && std::isfinite(r)))
    throw DeriveError{loc, "R027", "the radius of @o must be a finite number from 0, not " + std::to_string(r)};
  // The disc lies at z = 0 of its box: the box's X and Y are the turtle's X and U (scope
  // Z), its Z is -H, which keeps the frame right-handed.
  rt::Scope box = st.scope;
  box.axes.col(1) = st.scope.Z();
  box.axes.col(2) = -st.scope.Y();
  box.P -= r * (st.scope.X() + st.scope.Z());
  box.S = rt::Vec3::Constant(2 * r);
  d_.placeInstance(asset, box, d_.segmentSymbol(), nullptr, 0, loc);
}

// lpfg's @R(hx, hy, hz, ux, uy, uz) (SetHead): H = h / |h|, L = u x H normalised, U = H x L
// (u need only not be parallel to h).
void TurtleCommands::setHeading(State& st, const double* args, ir::Loc loc) {
  const rt::Vec3 h(args[0], args[1], args[2]), u(args[3], args[4], args[5]);
  const rt::Vec3 left = u.cross(h);
  if (!(h.allFinite() && u.allFinite() && h.norm() > 1e-12 && left.norm() > 1e-12 * u.norm() * h.norm()))
    throw DeriveError{loc, "R027", "@R needs a finite heading and up vector that are not zero and not parallel"};
  const rt::Vec3 heading = h.normalized(), l = left.normalized();
  st.scope.axes.col(1) = heading;
  st.scope.axes.col(0) = -l;
  st.scope.axes.col(2) = heading.cross(l);
}

// ABOP eq. 2.4: the heading H (scope Y) turns about H x T by e |H x T| radians, towards
// T, and L, U with it (one rotation of the whole frame keeps it orthonormal; the axes
// are renormalised against drift over long branches). Along T or -T nothing turns.
void TurtleCommands::bend(rt::Scope& scope, const Tropism& tropism) {
  const rt::Vec3 axis = scope.Y().cross(tropism.direction);
  const double s = axis.norm();
  if (!(s > 1e-12)) return;
  const Eigen::AngleAxisd rotation(tropism.elasticity * s, axis / s);
  const rt::Vec3 h = (rotation * scope.Y()).normalized();
  const rt::Vec3 x = (rotation * scope.X() - (rotation * scope.X()).dot(h) * h).normalized();
  scope.axes.col(1) = h;
  scope.axes.col(0) = x;
  scope.axes.col(2) = x.cross(h);
}

// lpfg's generalized cylinders (cpfg tutorial ch. 4): @Gs starts one at the turtle, @Gc(n)
// adds a control point with n strips (default 1) from the last, @Ge(n) adds the last and
// draws the tube (generalized_cylinder.h). L-Py writes @Gc to start one and @Ge to end it,
// each F in between a control point: an @Gc with no cylinder open starts one so. A
// cylinder belongs to the branch that started it: in a branch inside it F draws segments
// and @Gc starts a cylinder of the branch's own. The query modules' pass draws nothing.
void TurtleCommands::cylinderCommand(State& st, ir::TurtleOp op, const double* args, uint32_t n, ir::Loc loc) {
  if (!drawing_) return;
  OpenCylinder* tube = openCylinder(st);
  const auto start = [&](bool lpy) {
    cylinders_.push_back({{controlPoint(st, nullptr, 0, loc)}, st.scope.Z(), d_.scopeStackSize(), lpy, true, loc});
    st.cylinder = int32_t(cylinders_.size() - 1);
  };
  switch (op) {
    case ir::TurtleOp::CylinderStart:
      if (tube)
        throw DeriveError{loc, "R027", "@Gs while the generalized cylinder started at line " +
                                           std::to_string(tube->start.line) + ":" + std::to_string(tube->start.col) +
                                           " is open: end it with @Ge first"};
      start(false);
      break;
    case ir::TurtleOp::CylinderPoint:
      if (tube) {
        tube->points.push_back(controlPoint(st, args, n, loc));
      } else if (n == 0) {
        start(true);
      } else {
        throw DeriveError{loc, "R027", "@Gc(n) is lpfg's control point: it needs a generalized cylinder started by "
                                       "@Gs in this branch (L-Py's @Gc, without an argument, starts one)"};
      }
      break;
    default: {  // @Ge
      if (!tube)
        throw DeriveError{loc, "R027", "@Ge without a generalized cylinder started in this branch (by @Gs, or "
                                       "L-Py's @Gc)"};
      tube->points.push_back(controlPoint(st, args, n, loc));
      const CylinderSweep sweep = sweepGeneralizedCylinder(tube->points, tube->up, d_.module().turtle.sides);
      tube->open = false;
      std::vector<CylinderControlPoint>().swap(tube->points);
      st.cylinder = -1;
      if (sweep.vertices.empty()) break;  // every control point in one place: nothing to draw
      rt::Mesh mesh;
      mesh.positions.resize(3 * sweep.vertices.size());
      for (size_t v = 0; v < sweep.vertices.size(); ++v)
        for (int d = 0; d < 3; ++d) mesh.positions[3 * v + size_t(d)] = float(sweep.vertices[v][d]);
      mesh.indices.resize(sweep.triangles.size());
      std::copy(sweep.triangles.begin(), sweep.triangles.end(), mesh.indices.begin());
      d_.placeTurtleMesh(std::move(mesh), st.scope, d_.segmentSymbol(), loc);
      break;
    }
  }
}

TurtleCommands::OpenCylinder* TurtleCommands::openCylinder(const State& st) {
  if (st.cylinder < 0 || size_t(st.cylinder) >= cylinders_.size()) return nullptr;
  OpenCylinder& c = cylinders_[size_t(st.cylinder)];
  return c.open && c.depth == d_.scopeStackSize() ? &c : nullptr;
}

// The turtle's position and heading, half its width as the radius, and the strips `n`
// asks for (default 1).
CylinderControlPoint TurtleCommands::controlPoint(const State& st, const double* args, uint32_t n, ir::Loc loc) const {
  const double strips = n > 0 ? args[0] : 1.0;
  if (!(strips >= 1 && strips <= 10000 && strips == std::floor(strips)))
    throw DeriveError{loc, "R027", "the strips of a generalized cylinder's piece must be a whole number from 1 to "
                                   "10000, not " + std::to_string(strips)};
  if (!(st.width >= 0 && std::isfinite(st.width)))
    throw DeriveError{loc, "R027", "the width at a generalized cylinder's control point must be a finite number "
                                   "from 0, not " + std::to_string(st.width)};
  return {st.scope.P, st.scope.Y(), 0.5 * st.width, uint32_t(strips)};
}

// A cylinder never ended is not drawn: one R032 per module that started such cylinders.
void TurtleCommands::endCylinders(std::vector<rt::DeriveMessage>& messages) {
  std::vector<std::pair<ir::Loc, size_t>> unended;
  for (const OpenCylinder& c : cylinders_) {
    if (!c.open) continue;
    auto same = [&](const auto& u) { return u.first.line == c.start.line && u.first.col == c.start.col; };
    auto it = std::find_if(unended.begin(), unended.end(), same);
    if (it == unended.end())
      unended.push_back({c.start, 1});
    else
      ++it->second;
  }
  for (const auto& [loc, count] : unended)
    messages.push_back({false, "R032", loc.line, loc.col,
                        std::to_string(count) + " generalized cylinder" + (count == 1 ? "" : "s") +
                            " started here never ended with @Ge in the branch that started " +
                            (count == 1 ? "it" : "them") + ": not drawn"});
  cylinders_.clear();
}

void TurtleCommands::drawSymbol(const ir::Symbol& sym, const rt::Scope& scope, const double* params) {
  if (sym.name != "F") return;
  State st;
  st.scope = scope;
  st.width = d_.module().turtle.width;
  command(st, ir::TurtleOp::Forward, params, sym.slotCount > 0 ? 1 : 0, {});
}

}  // namespace fgsg::backend
