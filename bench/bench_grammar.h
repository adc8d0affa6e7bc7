// Shared by the benchmark programs: a grammar file compiled to IR, or the program stops
// with the diagnostics (a benchmark has nothing sensible to measure otherwise).
#pragma once

#include "frontend/diagnostics.h"
#include "ir/pipeline.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace fgsg::bench {

inline ir::Module compileGrammar(frontend::SourceFile file) {
  frontend::Diagnostics diags(&file);
  ir::Module m;
  if (!ir::compileSource(file, m, diags)) {
    diags.print(std::cerr);
    std::exit(1);
  }
  return m;
}

inline ir::Module compileGrammarFile(const std::string& path) {
  frontend::SourceFile file;
  std::string error;
  if (!ir::readSourceFile(path, file, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    std::exit(1);
  }
  return compileGrammar(file);
}

// A grammar given as text (the benchmarks' own), named bench.fgsg in diagnostics.
inline ir::Module compileGrammarText(const std::string& text) {
  return compileGrammar(frontend::SourceFile::make("bench.fgsg", text));
}

}  // namespace fgsg::bench
