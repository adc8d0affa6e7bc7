// The synthesis examples a grammar names (`Synthesize("file", nx, ny, nz)`): found and
// loaded the same way when deriving and by `fgsg check` beforehand, so that a file that
// cannot be used gives one message, at the call, from both.
#pragma once

#include "ir/ir.h"
#include "runtime/synthesis/continuous/example_file.h"
#include "runtime/synthesis/continuous/example_solid.h"
#include "runtime/synthesis/example.h"

#include <string>
#include <vector>

namespace fgsg::backend {

struct SynthesizeCall {
  std::string example;  // the file name as written
  ir::Loc at;           // the Synthesize call
};

// Every Synthesize call of the module (axiom and rules, bodies included), in source order.
std::vector<SynthesizeCall> synthesizeCalls(const ir::Module& m);

// Loads `name` from the first of `dirs` that holds it (as assets are found). False with
// `message` ("Synthesize: cannot use the example ...", the file's own diagnostics after).
bool loadSynthesisExample(const std::string& name, const std::vector<std::string>& dirs,
                          rt::synthesis::Example& out, std::string& message);

// Loads a polygonal example (continuous synthesis, Merrell ch. 4; which files are:
// rt::synthesis::continuous::isPolygonalExampleFile) as loadSynthesisExample does the others.
bool loadContinuousExample(const std::string& name, const std::vector<std::string>& dirs,
                           rt::synthesis::continuous::ExampleSolid& out, std::string& message,
                           rt::Deadline* deadline = nullptr);

}  // namespace fgsg::backend
