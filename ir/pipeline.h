// The whole front half in one call: parse -> semantic analysis -> lowering -> constant
// folding -> verification. Used by the CLI, the REPL, the tests and the benchmarks.
#pragma once

#include "frontend/diagnostics.h"
#include "ir/ir.h"

#include <string>

namespace fgsg::ir {

struct CompileTimes {
  double parseSeconds = 0, analyzeSeconds = 0, lowerSeconds = 0;
};

// Returns false when the grammar has errors (they are in `diags`). A module that fails
// verification is a compiler bug: reported as an internal error diagnostic. The modules
// the grammar imports are read (frontend/imports.h) and added to `file`.
// `keep`: where the parsed program (its modules merged) is kept, also when it has errors:
// fgsg lsp reads its declarations without parsing twice.
bool compileSource(frontend::SourceFile& file, Module& out, frontend::Diagnostics& diags,
                   CompileTimes* times = nullptr, frontend::Program* keep = nullptr);

// Reads a file into a SourceFile; false with a message when it cannot be read.
bool readSourceFile(const std::string& path, frontend::SourceFile& out, std::string& error);

}  // namespace fgsg::ir
