#include "cli/compile_file.h"

#include <iostream>

namespace fgsg::cli {

std::unique_ptr<CompiledFile> compileFile(const std::string& path, bool printWarnings) {
  auto out = std::make_unique<CompiledFile>();
  std::string error;
  if (!ir::readSourceFile(path, out->source, error)) {
    std::cerr << "fgsg: " << error << "\n";
    return nullptr;
  }
  frontend::Diagnostics diags(&out->source);
  const bool ok = ir::compileSource(out->source, out->module, diags, &out->times);
  for (const auto& d : diags.all()) {
    if (d.severity == frontend::Severity::Warning) ++out->warnings;
    if (d.severity == frontend::Severity::Error || printWarnings) std::cerr << diags.format(d) << "\n";
  }
  if (!ok) {
    std::cerr << diags.errorCount() << " error" << (diags.errorCount() == 1 ? "" : "s")
              << " in " << path << "\n";
    return nullptr;
  }
  return out;
}

}  // namespace fgsg::cli
