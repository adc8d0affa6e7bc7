// lpfg's and L-Py's syntax that fgsg does not support yet, found among the tokens before
// parsing, so a user who writes it gets one located E048 naming it (issue 48) instead of
// a syntax error about what follows, or nothing: the environmental query `?E(...)` (Mech
// and Prusinkiewicz 1996), `?` written against the `E` and the `E` against its '(': the
// module is dropped. A query that is a rule's whole left context goes with its '<'. (The turtle's query modules ?P ?H ?U ?L
// are supported: frontend/query_modules.h; lpfg's `#consider` is read by
// frontend/context_lists.h.)
#pragma once

#include "frontend/diagnostics.h"

#include <memory>
#include <vector>

#include "antlr4-runtime.h"

namespace fgsg::frontend {

void dropLsystemSyntaxNotYetSupported(std::vector<std::unique_ptr<antlr4::Token>>& tokens, Diagnostics& diags);

}  // namespace fgsg::frontend
