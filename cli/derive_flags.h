// The options every deriving command shares (run, field, view), declared once so that
// their spelling, checks and messages agree.
#pragma once

#include "backend/engine.h"
#include "cli/command_line.h"
#include "runtime/derivation.h"

namespace fgsg::cli {

// --engine jit|interp.
void engineFlag(CommandLine& cl, backend::Engine& engine);
// --set name=value, repeatable: an attr's value.
void setFlag(CommandLine& cl, rt::DeriveOptions& derive);
// --surface MESH, --surface-size S, --repair-surface: the surface grown on.
void surfaceFlags(CommandLine& cl, rt::DeriveOptions& derive);

}  // namespace fgsg::cli
