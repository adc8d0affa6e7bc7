// Reading a REPL input into statements (repl_session.h): where each statement starts and
// ends in the input's tokens, its text as typed, and the key of what it defines.
#pragma once

#include "cli/repl_session.h"
#include "frontend/diagnostics.h"

#include <memory>
#include <vector>

namespace fgsg::cli::repl {

// The statements of a syntactically valid input, split at each top-level ';' (explicit or
// implicit) and keyed. `priority`: the `priority N:` in force before the input, then the
// one in force after it.
std::vector<Statement> splitStatements(const std::shared_ptr<const frontend::SourceFile>& input,
                                       int& priority);

// Whether the statements contain a rule or an axiom, something to derive from.
bool hasStart(const std::vector<Statement>& list);

}  // namespace fgsg::cli::repl
