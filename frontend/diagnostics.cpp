#include "frontend/diagnostics.h"

#include <algorithm>
#include <ostream>
#include <sstream>

namespace fgsg::frontend {

namespace {

// Columns count characters (code points, as the lexer does), not bytes.
bool isUtf8Continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

const char* severityWord(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

// The line under the source line: '^' at the range's first column, '~' under the rest
// of the range when it ends on the same line. Tabs before the caret are copied so the
// caret lines up whatever the terminal's tab width.
std::string caretLine(const std::string& sourceLine, const SourceRange& range) {
  std::string out;
  int col = 1;
  size_t i = 0;
  while (col < range.begin.col && i < sourceLine.size()) {
    out += sourceLine[i] == '\t' ? '\t' : ' ';
    ++i;
    while (i < sourceLine.size() && isUtf8Continuation(sourceLine[i])) ++i;
    ++col;
  }
  for (; col < range.begin.col; ++col) out += ' ';  // column past the end of the line
  out += '^';
  if (range.end.line == range.begin.line) {
    for (int c = range.begin.col + 1; c <= range.end.col; ++c) out += '~';
  }
  return out;
}

}  // namespace

SourceFile SourceFile::make(std::string name, std::string text) {
  SourceFile file;
  file.name = std::move(name);
  file.text = std::move(text);
  std::string line;
  for (char c : file.text) {
    if (c == '\n') {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      file.lines.push_back(std::move(line));
      line.clear();
    } else {
      line += c;
    }
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  file.lines.push_back(std::move(line));
  return file;
}

void Diagnostics::error(const std::string& code, const SourceRange& at, std::string message) {
  list_.push_back({Severity::Error, code, std::move(message), at});
  ++errorCount_;
}

void Diagnostics::warning(const std::string& code, const SourceRange& at, std::string message) {
  list_.push_back({Severity::Warning, code, std::move(message), at});
}

void Diagnostics::note(const SourceRange& at, std::string message) {
  list_.push_back({Severity::Note, "", std::move(message), at});
}

// `file:line:col: error[E012]: message`, the source line, the caret line; no trailing
// newline. A diagnostic without a location (line 0) is the first line only.
std::string Diagnostics::format(const Diagnostic& d) const {
  std::ostringstream out;
  const std::string fileName = file_ ? file_->name : std::string("<input>");
  const bool located = d.range.begin.line > 0;
  out << fileName << ':';
  if (located) out << d.range.begin.line << ':' << std::max(d.range.begin.col, 1) << ':';
  out << ' ' << severityWord(d.severity);
  if (d.severity != Severity::Note && !d.code.empty()) out << '[' << d.code << ']';
  out << ": " << d.message;

  if (located && file_ && d.range.begin.line <= static_cast<int>(file_->lines.size())) {
    const std::string& line = file_->lines[d.range.begin.line - 1];
    SourceRange shown = d.range;
    shown.begin.col = std::max(shown.begin.col, 1);
    out << '\n' << line << '\n' << caretLine(line, shown);
  }
  return out.str();
}

void Diagnostics::print(std::ostream& out) const {
  for (const Diagnostic& d : list_) out << format(d) << '\n';
}

}  // namespace fgsg::frontend
