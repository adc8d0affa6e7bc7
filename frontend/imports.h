// `import "path" [as name] [(attr = value, ...)];`: a grammar's modules. Each imported file
// is parsed as a grammar of its own (its lines numbered after the ones before, so a
// diagnostic names the module's file and line), its own imports first; with `as name`
// every name it declares — symbols, attrs, consts, fields, textures, tilesets — becomes
// `name.X`, and its rules and declarations join the importer's. What belongs to a whole
// program stays the importer's: a module's axiom (and its Axiom/start rules), `derive`,
// `surface`, `turtle`, `collision` and `#ignore` apply only when the module runs alone.
// The files a module names (assets, images, fields) are looked for beside it first.
//
// Search order for a path (".fgsg" added when it has no extension): "std/..." names the
// standard library; any other path is looked up beside the importing file, then in each
// folder of FGSG_PATH (':'-separated), then in the standard library. A cycle of imports
// and a name two imports both declare (or a symbol given rules by two of them) are
// errors that show both sites.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

#include <string>
#include <vector>

namespace fgsg::frontend {

// Where imports are looked for besides the importing file's folder.
struct ImportSearch {
  std::vector<std::string> path;  // FGSG_PATH's folders, in order
  std::string stdlib;             // the standard library's folder ("std/..." paths)
};

// FGSG_PATH, and the standard library: $FGSG_STDLIB, else share/fgsg/stdlib beside the
// running program's bin/, else the install prefix's, else the source tree's stdlib/.
ImportSearch defaultImportSearch();

// Reads the modules `program` (the grammar of `file`) imports — or takes them from `file`
// when its text carries them, as a compiled library's does — and merges them into
// `program`; `file` gets each module's text and lines. False when an import failed
// (reported in `diags`).
bool resolveImports(SourceFile& file, Program& program, Diagnostics& diags,
                    const ImportSearch& search = defaultImportSearch());

}  // namespace fgsg::frontend
