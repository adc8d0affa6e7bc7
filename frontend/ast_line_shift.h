// Moving a parsed statement's AST to other lines (statement reuse, frontend/statement_reuse.h):
// a statement taken over after lines were inserted or deleted above it has every place in
// it moved by the same number of lines; columns stay.
#pragma once

#include "frontend/ast.h"

namespace fgsg::frontend {

void shiftLines(Rule& rule, int lines);
void shiftLines(ValueDecl& value, int lines);

}  // namespace fgsg::frontend
