// The `.cga` dialect (CityEngine's CGA): which files are read as CGA, and parsing them into
// the AST every engine runs (frontend/ast.h). See docs/cga.md, "CGA for CityEngine users".
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

#include <string>
#include <utility>
#include <vector>

namespace fgsg::frontend {

// A file named *.cga, or whose first statement is `dialect cga;`.
bool isCgaSource(const std::string& name, const std::string& text);

// Whether .fgsg text looks like CityEngine CGA (`-->`, `@StartRule`, `version "...`): a hint
// for the fgsg dialect's syntax errors. The line where it shows, or 0.
int cgaLookingLine(const std::string& text);

// Parses and translates CGA text into `out`. `startRule` overrides the file's @StartRule
// (empty: keep it); `Style$Rule` or `Style$` chooses a style. `styleFromImporter`: the file
// is an import read in its importer's style, which it need not have. False when an error
// was reported.
bool parseCgaText(const std::string& name, const std::string& text, Program& out, Diagnostics& diags,
                  const std::string& startRule = "", bool styleFromImporter = false);

// A CityEngine operation name (`taper`, `rotateScope`, `color` ...): the fgsg dialect
// refuses one used as a shape symbol with arguments.
bool isCityEngineOperationName(const std::string& name);

// For an editor's completion in a .cga file: CityEngine's operations this dialect knows
// (sorted; those not translated yet are E800 where used), and the CityEngine functions it
// translates, each with its argument forms.
std::vector<std::string> cityEngineOperationNames();
std::vector<std::pair<std::string, std::string>> cityEngineFunctionSignatures();
// The members of CityEngine's geometry object it translates (`area` for geometry.area() ...).
std::vector<std::string> cityEngineGeometryFunctionNames();

}  // namespace fgsg::frontend
