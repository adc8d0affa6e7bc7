// The lists of modules context matching sees or steps over, as lpfg, cpfg and L-Py write
// them, read as fgsg's `#ignore: ...;` declaration (grammar/Fgsg.g4's ignoreDecl):
//  * lpfg's `#consider: A B;` ('#' written against `consider`), cpfg's and L-Py's
//    `consider: A B` — context matching sees only the modules listed;
//  * cpfg's and L-Py's `ignore: + -` — as fgsg's `#ignore: + -;`.
// The words become one IGNORE token whose text tells the two apart (`#consider`,
// `consider`: the modules considered; frontend/ast_builder.cpp). The bare forms are read
// so only first on their line, with modules after the colon on that line and no arrow
// there (`ignore: x > 1 -> B` stays a rule for a symbol `ignore`). The ';' is optional,
// as after `#ignore` (an implicit semicolon ends the line).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "antlr4-runtime.h"

namespace fgsg::frontend {

void readContextListDeclarations(std::vector<std::unique_ptr<antlr4::Token>>& tokens);

// Whether an ignore declaration's keyword as written (its token's text) lists the modules
// considered (`#consider`, `consider`) rather than those ignored.
inline bool listsConsideredModules(const std::string& keyword) {
  return keyword == "#consider" || keyword == "consider";
}

}  // namespace fgsg::frontend
