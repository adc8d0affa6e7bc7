// cpfg's and lpfg's query modules `?P(x, y, z)`, `?H(...)`, `?U(...)`, `?L(...)`
// (Prusinkiewicz, James and Mech 1994, "Synthetic topiary") and the environmental query
// `?E(...)` (Mech and Prusinkiewicz 1996): `?` written against the
// letter and the letter against its '(' becomes one name token, `?P`, so the parser reads
// a query module as any other module of the string (a symbol of the grammar). The
// parallel derivation fills its arguments with the turtle's position, heading, up or left
// vector, or ?E's with the grammar's first field there, after each step
// (backend/engine/query_modules.cpp). `c ? P(1) : 2` with spaces
// stays a conditional expression.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "antlr4-runtime.h"

namespace fgsg::frontend {

void joinQueryModules(std::vector<std::unique_ptr<antlr4::Token>>& tokens);

// Whether `name` is a query module's (`?P`, `?H`, `?U`, `?L`, `?E`), or with `letterOnly` its
// letter (`P` ...).
bool isQueryModuleName(const std::string& name, bool letterOnly = false);

}  // namespace fgsg::frontend
