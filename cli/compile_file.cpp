#include "cli/compile_file.h"

#include <iostream>

namespace fgsg::cli {

std::unique_ptr<CompiledFile> compileFile(const std::string& path, bool printWarnings, const std::string& startRule) {
  return compileFile(path, std::cerr, printWarnings, startRule);
}

std::unique_ptr<CompiledFile> compileFile(const std::string& path, std::ostream& diagnostics, bool printWarnings,
                                          const std::string& startRule) {
  std::ostream& err = diagnostics;
  auto out = std::make_unique<CompiledFile>();
  std::string error;
  if (!ir::readSourceFile(path, out->source, error)) {
    err << "fgsg: " << error << "\n";
    return nullptr;
  }
  out->source.startRule = startRule;
  frontend::Diagnostics diags(&out->source);
  const bool ok = ir::compileSource(out->source, out->module, diags, &out->times);
  for (const auto& d : diags.all()) {
    if (d.severity == frontend::Severity::Warning) ++out->warnings;
    if (d.severity == frontend::Severity::Error || printWarnings) err << diags.format(d) << "\n";
  }
  if (!ok) {
    err << diags.errorCount() << " error" << (diags.errorCount() == 1 ? "" : "s")
              << " in " << path << "\n";
    return nullptr;
  }
  return out;
}

}  // namespace fgsg::cli
