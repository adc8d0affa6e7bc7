// Errors in synthesis inputs (example grids, tile sets, images, masks, CLI values),
// reported the project way: `file:line:col: error[E7xx]: message`, the source line and a
// caret. Loaders collect several and never throw.
#pragma once

#include <string>
#include <vector>

namespace fgsg::rt::synthesis {

struct Diagnostic {
  std::string file;
  int line = 0;    // 1-based; 0 when the error is about the whole file
  int column = 0;  // 1-based; 0 when unknown
  std::string code;  // "E701"
  std::string message;
  std::string sourceLine;  // the offending line, for the caret display
};

using Diagnostics = std::vector<Diagnostic>;

// "file:line:col: error[E701]: message\n  source line\n  ^\n"
std::string formatDiagnostic(const Diagnostic& d);
std::string formatDiagnostics(const Diagnostics& ds);

}  // namespace fgsg::rt::synthesis
