// Completion inside an import's path string: `import "..."` (fgsg) and
// `import name : "..."` (.cga). The modules offered are those the import would find, as
// frontend/imports.cpp looks for them: files beside the document (an untitled buffer: the
// working directory), in FGSG_PATH's folders, and the standard library's as "std/...".
#pragma once

#include "cli/lsp/lsp_analysis.h"

#include <optional>
#include <string>

namespace fgsg::cli::lsp {

// The part of an import's path written before the cursor (`import "std/c` -> "std/c"),
// or nothing where `beforeCursor` (the line up to the cursor) is not inside one.
std::optional<std::string> importPathBeforeCursor(const std::string& beforeCursor);

// The completion items for an import path of the document at `documentPath` of which
// `typed` is written, ending at (line, character): each module's import name ("facade",
// "lib.cga", "std/cga/facade") and the folders ("parts/") that start like it.
Json importPathItems(const std::string& documentPath, const std::string& typed, int line, int character);

}  // namespace fgsg::cli::lsp
