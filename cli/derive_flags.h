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
// --start-rule NAME: a .cga grammar's rule for its start shapes instead of its @StartRule
// (compileFile checks it: a rule the file lacks, or an fgsg grammar, is error E803).
void startRuleFlag(CommandLine& cl, std::string& startRule);
// --surface MESH, --surface-size S, --repair-surface: the surface grown on.
void surfaceFlags(CommandLine& cl, rt::DeriveOptions& derive);

// --step N: an L-system (`derive parallel`) rewritten N steps, 0 its axiom, instead of
// its whole length (rt::DeriveOptions::parallelStep).
void stepFlag(CommandLine& cl, rt::DeriveOptions& derive);
// --step against the compiled grammar `file`: false with `error` for a grammar that is no
// L-system. A step past the derivation length is the
// length, as lpfg's animate mode stops there: `warning` then says so. `flag` names the
// setting in both (the REPL's `:step`).
bool checkStepFlag(const ir::Module& m, const std::string& file, rt::DeriveOptions& derive, std::string& error,
                   std::string& warning, const std::string& flag = "--step");

// --instancing auto|on|off, --group-by symbol|rule|label|none, --split-output DIR: the
// output's layout (runtime/output/scene.h, cli/scene_output.h). A glTF output is a scene
// by default (auto / symbol); `--instancing off --group-by none` gives the one flattened
// mesh of before. OBJ is flattened unless --group-by is given; PLY is always flattened.
struct SceneFlags {
  rt::output::Instancing instancing = rt::output::Instancing::Auto;
  rt::output::GroupBy groupBy = rt::output::GroupBy::Symbol;
  bool instancingGiven = false, groupByGiven = false;
  std::string splitOutput;  // --split-output: a file per start shape in this folder
  bool quantize = false;    // --quantize: the glTF scene's vertex data 16-bit (gltf_writer.h)
};
void sceneFlags(CommandLine& cl, SceneFlags& scene);

}  // namespace fgsg::cli
