// Lowering: the analysed AST becomes an ir::Module. Runs only on programs that passed
// semantic analysis, so it reports nothing: every name and type is already resolved.
#pragma once

#include "frontend/ast.h"
#include "frontend/sema.h"
#include "ir/ir.h"

namespace fgsg::ir {

Module lowerProgram(const frontend::Program& program, const frontend::SemaResult& sema);

}  // namespace fgsg::ir
