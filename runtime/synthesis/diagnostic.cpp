#include "runtime/synthesis/diagnostic.h"

namespace fgsg::rt::synthesis {

std::string formatDiagnostic(const Diagnostic& d) {
  std::string s = d.file;
  if (d.line > 0) {
    s += ":" + std::to_string(d.line);
    if (d.column > 0) s += ":" + std::to_string(d.column);
  }
  s += ": error[" + d.code + "]: " + d.message + "\n";
  if (!d.sourceLine.empty()) {
    s += "  " + d.sourceLine + "\n";
    if (d.column > 0) s += "  " + std::string(size_t(d.column - 1), ' ') + "^\n";
  }
  return s;
}

std::string formatDiagnostics(const Diagnostics& ds) {
  std::string s;
  for (const auto& d : ds) s += formatDiagnostic(d);
  return s;
}

}  // namespace fgsg::rt::synthesis
