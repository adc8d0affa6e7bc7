// lpfg's and L-Py's syntax that fgsg does not support yet, found among the tokens before
// parsing, so a user who writes it gets one located E048 naming it (issue 48) instead of
// a syntax error about what follows, or nothing:
//  * `#consider: A B;` (context matching sees only the symbols listed): the whole
//    statement, up to its ';' or the end of its line, is dropped after the error;
//  * the query modules `?P(x, y, z)`, `?H(...)`, `?U(...)`, `?L(...)` and the
//    environmental query `?E(...)` (ABOP §1.10; Prusinkiewicz et al. 1994), `?` written
//    against the letter and the letter against its '(': the module is dropped. `c ? P(1)
//    : 2` with spaces stays a conditional expression. A query that is a rule's whole left
//    context goes with its '<'.
#pragma once

#include "frontend/diagnostics.h"

#include <memory>
#include <vector>

#include "antlr4-runtime.h"

namespace fgsg::frontend {

void dropLsystemSyntaxNotYetSupported(std::vector<std::unique_ptr<antlr4::Token>>& tokens, Diagnostics& diags);

}  // namespace fgsg::frontend
