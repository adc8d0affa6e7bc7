// Reads and compiles a grammar file for a subcommand, printing its diagnostics.
#pragma once

#include "frontend/diagnostics.h"
#include "ir/ir.h"
#include "ir/pipeline.h"

#include <memory>
#include <ostream>
#include <string>

namespace fgsg::cli {

struct CompiledFile {
  frontend::SourceFile source;
  ir::Module module;
  ir::CompileTimes times;
  int warnings = 0;
};

// Returns null after printing diagnostics (or the read error) to stderr. `startRule`
// (--start-rule): a .cga grammar's rule for its start shapes instead of its @StartRule; an
// error (E803) for a rule the file lacks, or for an fgsg grammar.
std::unique_ptr<CompiledFile> compileFile(const std::string& path, bool printWarnings = true,
                                          const std::string& startRule = "");
// The same, printing to `diagnostics` (fgsg view shows them in its page).
std::unique_ptr<CompiledFile> compileFile(const std::string& path, std::ostream& diagnostics, bool printWarnings,
                                          const std::string& startRule = "");

}  // namespace fgsg::cli
