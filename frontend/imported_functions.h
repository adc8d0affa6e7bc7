// Calls of an imported `.cga` file's functions and consts: `import F : "facade.cga"`, then
// `F.windowWidth(3)` or `F.floorCount`. A `.cga` file inlines its own functions where they
// are used; an importer's call of one is left as a call (a Call `F.windowWidth`, or the
// Ident `F.floorCount` for one without parameters) until the module is read, and is then
// replaced here by the function's body (Program::functions) with the arguments in place
// of its parameters. The body reads the module's attrs under their imported names
// (`F.tileWidth`), so the importer's `F.tileWidth = ...` and `--set F.tileWidth=...` reach it.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

#include <string>

namespace fgsg::frontend {

// Replaces the calls `alias.name(...)` (and `alias.name` of a function without
// parameters) in `importer` — its attrs, rules and its own functions — by the bodies of
// `module`'s functions, which are already qualified with `alias`. A name the module has no
// function of (and no attr), a wrong number of arguments, or a body that did not translate
// is an error at the call. `modulePath` is the import's path as written, for messages.
void inlineImportedFunctions(Program& importer, const std::string& alias, const Program& module,
                             const std::string& modulePath, Diagnostics& diags);

}  // namespace fgsg::frontend
