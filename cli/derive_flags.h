// The options every deriving command shares (run, field, view), declared once so that
// their spelling, checks and messages agree.
#pragma once

#include "backend/engine.h"
#include "cli/command_line.h"
#include "runtime/derivation.h"
#include "runtime/output/scene.h"

namespace fgsg::cli {

// --engine jit|interp.
void engineFlag(CommandLine& cl, backend::Engine& engine);
// --set name=value, repeatable: an attr's value.
void setFlag(CommandLine& cl, rt::DeriveOptions& derive);
// --surface MESH, --surface-size S, --repair-surface: the surface grown on.
void surfaceFlags(CommandLine& cl, rt::DeriveOptions& derive);

// --instancing auto|on|off, --group-by symbol|rule|label|none: the glTF scene's layout
// (runtime/output/scene.h). Both left at off / none (the default for now): the one
// flattened mesh of before.
struct SceneFlags {
  rt::output::Instancing instancing = rt::output::Instancing::Off;
  rt::output::GroupBy groupBy = rt::output::GroupBy::None;
  bool flattened() const {
    return instancing == rt::output::Instancing::Off && groupBy == rt::output::GroupBy::None;
  }
};
void sceneFlags(CommandLine& cl, SceneFlags& scene);

}  // namespace fgsg::cli
