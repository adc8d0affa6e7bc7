// Positions as LSP counts them (0-based lines, columns in UTF-16 code units) against the
// front end's (1-based lines, columns in code points) and the bytes of a document's
// UTF-8 text; and file:// URIs against paths.
#pragma once

#include <string>

namespace fgsg::cli::lsp {

// The UTF-16 units taken by the first `codePoints` characters of `line` (each column past
// the line's end counts one: the front end points one past it at an end of line).
int utf16Units(const std::string& line, int codePoints);
// The byte in `line` where UTF-16 column `units` falls (clamped to the line's end).
size_t byteAtUtf16(const std::string& line, int units);
// The byte offset in `text` of (line, UTF-16 column), clamped to the text.
size_t offsetAt(const std::string& text, int line, int units);
// Line `line` (0-based) of `text`, without its end of line; empty past the end.
std::string lineAt(const std::string& text, int line);

// "file:///a%20b/x.fgsg" -> "/a b/x.fgsg"; another scheme gives its text after the last '/'
// (an untitled buffer: imports are then looked for in the working directory).
std::string pathOfUri(const std::string& uri);
std::string uriOfPath(const std::string& path);

}  // namespace fgsg::cli::lsp
