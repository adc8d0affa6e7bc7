// CGA's shape operations (Müller et al. 2006): Subdiv, Repeat and Comp split the scope
// (or its geometry) into parts, each running a body; Footprint makes the shape a polygon
// lot; Offset sets its inside back from its edges; Extrude gives a footprint height; Roof
// builds a roof over it and runs its body on the roof. The geometry lives in the
// derivation's arena (runtime/cga/).
#pragma once

#include "backend/commands/command_family.h"

namespace fgsg::backend {

class Derivation;

class CgaCommands final : public CommandFamily {
 public:
  explicit CgaCommands(Derivation& derivation) : d_(derivation) {}

  std::vector<ir::OpKind> kinds() const override;
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) override;

 private:
  void split(const ir::Op& op, const double* a, State& st, Exec& ex, Frame& f);

  Derivation& d_;
};

}  // namespace fgsg::backend
