// `fgsg fmt`: an .fgsg grammar's canonical layout (docs/editors.md, "fgsg fmt").
//
// The formatter works on the token stream, not the AST, so nothing the AST does not keep
// is lost: every token is written again with the same text, every comment with its text,
// and only the whitespace between them changes. It keeps the author's line breaks (a line
// break can end a statement in .fgsg, grammar/Fgsg.g4) and normalises the rest:
// indentation by statement and bracket depth, one space after ',' and ':', around arrows,
// '=' and an expression's binary operators, none inside '( )' or before ';' and ',', at
// most one blank line in a row, no trailing blanks, one '\n' at the end. What it writes is
// lexed again and compared with the input's tokens; any difference is an error, never an
// output.
#pragma once

#include "frontend/diagnostics.h"

#include <string>

namespace fgsg::frontend {

// Formats `file`'s own text into `out`. False, with located errors in `diags`, when the
// text has syntax errors, is not UTF-8, or is a .cga grammar (not supported yet); `out`
// is then left empty. Formatting formatted text returns it unchanged.
bool formatGrammar(const SourceFile& file, std::string& out, Diagnostics& diags);

}  // namespace fgsg::frontend
