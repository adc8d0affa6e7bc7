// Parsing: source text -> AST. Syntax errors are reported as diagnostics (E001 for a
// lexical error, E002 for a syntax error) with the offending token's line and column;
// parsing recovers and continues so several mistakes are reported in one run.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

namespace fgsg::frontend {

// Returns false if any syntax error was reported; `out` then holds what could be built.
bool parseProgram(const SourceFile& file, Program& out, Diagnostics& diags);  // the grammar's own text
// Any text (an imported module's, behind blank lines that give it its place in the whole).
bool parseText(const std::string& name, const std::string& text, Program& out, Diagnostics& diags,
               const std::vector<std::string>& importAliases = {});

}  // namespace fgsg::frontend
