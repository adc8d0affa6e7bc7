// Two-stage parsing (ANTLR's recipe): parse first with SLL prediction and a strategy that
// gives up at the first syntax error; only where that fails parse again with full LL
// prediction, which reports the errors and recovers. SLL prediction never simulates the
// whole context, the bulk of ANTLR's time on a large grammar (fgsg lsp re-parses the
// document on every change); on input without errors it gives the tree LL would.
#pragma once

#include "antlr4-runtime.h"

namespace fgsg::frontend {

// Makes `parser` the first stage: SLL prediction, no error listeners, and an error
// strategy that throws antlr4::ParseCancellationException at the first syntax error.
void makeFirstStage(antlr4::Parser& parser);

// The tree `parseRule()` builds with a first-stage parser, or nullptr where it met a
// syntax error; the caller then rewinds the token stream and parses with the second stage.
template <class ParseRule>
auto tryFirstStage(ParseRule&& parseRule) -> decltype(parseRule()) {
  try {
    return parseRule();
  } catch (const antlr4::ParseCancellationException&) {
    return nullptr;
  }
}

}  // namespace fgsg::frontend
