// CityEngine's footprint-shaping and scope operations (ir::OpKind::ShapeOperation, issue
// #44): the op names the operation (op.str: AlignScopeToAxes, Setback, ShapeL ...), its
// arguments are evaluated numbers (a word as the number frontend/shape_operations.h gives
// it). Scope operations and geometry operations replace the running shape's scope and
// geometry; Setback, ShapeL/U/O and InnerRectangle with a body run their labelled parts.
// CgaCommands hands these ops here.
#pragma once

#include "backend/commands/command_family.h"

namespace fgsg::backend {

class Derivation;

void applyShapeOperation(Derivation& d, const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f);

}  // namespace fgsg::backend
