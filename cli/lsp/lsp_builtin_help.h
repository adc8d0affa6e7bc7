// The markdown an editor shows for a builtin name (hover, completion's documentation):
// its signature as code, then its doc from frontend/builtin_docs.cpp's table (the one
// docs/language.md's "Builtin reference" is generated from).
#pragma once

#include "cli/lsp/lsp_analysis.h"

#include <string>

namespace fgsg::cli::lsp {

// In a .fgsg document: a command, function, query (Scope.sx, Shape.*, Geometry.*,
// Feature.*, Lot.*), surface (torus ...), field source (curvature ...) or a member of a
// field the grammar declares (F1.vector1); "" for none.
std::string fgsgBuiltinHelp(const Analysis& analysis, const std::string& name);

// In a .cga document: a CityEngine operation, function or shape attribute, with the fgsg
// builtin it becomes and that builtin's doc; an operation the dialect knows but does not
// translate says so; "" for none.
std::string cgaBuiltinHelp(const std::string& name);

}  // namespace fgsg::cli::lsp
