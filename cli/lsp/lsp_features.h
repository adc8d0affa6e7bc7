// The language features, one file each: each takes a document's analysis (and text) and
// the request's position, and returns the LSP result.
#pragma once

#include "cli/lsp/lsp_analysis.h"

#include <string>

namespace fgsg::cli::lsp {

// textDocument/publishDiagnostics' params: what `fgsg check` says, with its codes and
// ranges. A diagnostic inside an imported module is shown on the document's import of it,
// its message prefixed with the module's file:line:col.
Json diagnosticsParams(const Analysis& analysis, const std::string& uri);

// textDocument/completion: the builtin commands and functions (frontend/builtins.h's
// tables; in a .cga file CityEngine's operations and functions instead) and the grammar's
// rules, attrs, consts and fields that start like the name being written at (line,
// character), builtins with their docs; after a '.', the queries (Scope.sx, a field's
// members; .cga: geometry.area, scope.sx ...); inside an import's path, the modules it may
// name (lsp_import_paths.h).
Json completion(const Analysis& analysis, const std::string& text, int line, int character);

// textDocument/hover: a builtin's signature and doc (lsp_builtin_help.h: the table
// docs/language.md's builtin reference is generated from), or a declaration's line.
Json hover(const Analysis& analysis, const std::string& text, int line, int character);

// textDocument/definition: where the rule, attr, const or field under the cursor is
// declared, in the document or a module it imports.
Json definition(const Analysis& analysis, const std::string& text, int line, int character);

// textDocument/references: every place the name under the cursor is written, in the
// document and in the module that declares it (a lexical search outside comments and
// strings: a rule parameter that shadows an attr's name is counted too).
Json references(const Analysis& analysis, const std::string& text, int line, int character, bool includeDeclaration);

// textDocument/rename: those places renamed, as a WorkspaceEdit; null with `error` for a
// new name that is not one or a place that names nothing of the grammar's.
Json rename(const Analysis& analysis, const std::string& text, int line, int character, const std::string& newName,
            std::string& error);

// textDocument/documentSymbol: the document's rules, attrs, consts and fields.
Json documentSymbols(const Analysis& analysis);

// textDocument/semanticTokens/full and /range: the document's tokens classified (rules and
// shape symbols, attrs, consts, fields, module aliases, rule parameters, builtin commands,
// operations and functions, queries, numbers, strings, comments, keywords), LSP's relative
// encoding with the types and modifiers of semanticTokensLegend(). `range`: null for the
// whole document, else an LSP Range whose lines are kept.
Json semanticTokensLegend();
Json semanticTokens(const Analysis& analysis, const std::string& text, const Json& range);

// textDocument/formatting: the document in `fgsg fmt`'s layout (frontend/format_grammar.h),
// as one edit of the whole text, or none when it is laid out so already; null with `error`
// (the first problem, file:line:col) for text it cannot format: a syntax error, a .cga file.
// The editor's tab size is not asked: the layout is the canonical one.
Json formatting(const std::string& path, const std::string& text, std::string& error);

}  // namespace fgsg::cli::lsp
