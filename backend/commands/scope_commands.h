// Scope and transforms: T, Rx/Ry/Rz/R, RS, S, Center and the [ ] stack (CGA's scope
// commands, ABOP's branches). On a surface, T traces along the first field and RS turns
// about the surface normal (commands/surface_world.h); on the plane both are plain
// vector algebra.
// translate, turn and push are inline: they are the hot path of every derivation.
#pragma once

#include "backend/commands/command_family.h"
#include "backend/commands/surface_world.h"
#include "backend/engine/sequential_string.h"
#include "backend/interp/joined_strings.h"

#include <memory>
#include <string>
#include <vector>

namespace fgsg::backend {

// Without a surface, patterns grow on the XY plane: RS() turns about its normal.
inline const rt::Vec3 kPlaneNormal = rt::Vec3::UnitZ();

class ScopeCommands final : public CommandFamily {
 public:
  // `surface`: the derivation's surface (null on the plane; set once the engine has
  // built it); `stack`: the derivation's shared [ ] stack; `deadline`: its
  // --max-seconds, which traces on the surface ask.
  // `strings`: the module's strings and those a string `+` joined (a colour given as a
  // string id: color("#" + hex)).
  ScopeCommands(const std::shared_ptr<const SurfaceWorld>& surface, std::vector<Saved>& stack,
                rt::Deadline& deadline, const JoinedStrings& strings)
      : surface_(surface), stack_(stack), deadline_(deadline), strings_(strings) {}

  std::vector<ir::OpKind> kinds() const override;
  void apply(const ir::Op& op, const double* a, uint32_t, State& st, Exec&, Frame&) override { command(st, op, a); }

  // Applies a scope command whose arguments are already evaluated.
  void command(State& st, const ir::Op& op, const double* a);

  // T: on the plane a vector addition in the scope's frame; on a surface a trace along
  // the first field (FGSG §4.3).
  void translate(rt::Scope& scope, double x, double y, double z) {
    if (surface_)
      surface_->translate(scope, x, y, z, &deadline_);
    else
      rt::translateLocal(scope, x, y, z);
  }

  void turn(rt::Scope& scope, int axis, double degrees) {
    double c, s;
    trig_.cosSin(degrees, c, s);
    rt::rotateLocal(scope, axis, c, s);
  }
  // Direct derivation turns as turn() does, with the cosine and sine of this memo.
  void cosSin(double degrees, double* out) { trig_.cosSin(degrees, out[0], out[1]); }

  void push(const State& st) {
    stack_.push_back({st.scope, st.geom, st.width, st.line, string_ ? string_->addOpen() : UINT32_MAX, st.tropism,
                      st.cylinder});
  }

  // A sequential derivation with contexts keeps its brackets in its string.
  void writeBracketsTo(SequentialString* string) { string_ = string; }

 private:
  void center(State& st, const ir::Op& op);

  const std::shared_ptr<const SurfaceWorld>& surface_;
  std::vector<Saved>& stack_;
  rt::Deadline& deadline_;
  const JoinedStrings& strings_;
  rt::TrigMemo trig_;
  SequentialString* string_ = nullptr;
};

}  // namespace fgsg::backend
