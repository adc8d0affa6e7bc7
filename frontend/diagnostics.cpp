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

namespace {

// Marks a module's text in SourceFile::text: "\n" kModuleMark key US name US importer US
// written "\n" text. Control characters no grammar contains (the lexer refuses them).
const std::string kModuleMark = "\x1e" "fgsg-module\x1f";
constexpr char kUnit = '\x1f';

void splitLines(const std::string& text, std::vector<std::string>& lines) {
  std::string line;
  for (char c : text) {
    if (c == '\n') {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines.push_back(std::move(line));
      line.clear();
    } else {
      line += c;
    }
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  lines.push_back(std::move(line));
}

}  // namespace

SourceFile SourceFile::make(std::string name, std::string text) {
  SourceFile file;
  file.name = std::move(name);
  const size_t first = text.find("\n" + kModuleMark);
  file.text = text.substr(0, first);
  splitLines(file.text, file.lines);
  file.mainLength_ = file.text.size();
  // A grammar with its modules (a compiled library's embedded text): the modules again.
  for (size_t at = first; at != std::string::npos;) {
    const size_t head = at + 1 + kModuleMark.size();
    const size_t eol = text.find('\n', head);
    const size_t next = eol == std::string::npos ? std::string::npos : text.find("\n" + kModuleMark, eol);
    if (eol == std::string::npos) break;
    std::vector<std::string> words;
    size_t from = head;
    for (size_t u; (u = text.find(kUnit, from)) != std::string::npos && u < eol; from = u + 1)
      words.push_back(text.substr(from, u - from));
    words.push_back(text.substr(from, eol - from));
    if (words.size() != 4) break;
    Module m{words[0], words[1], words[2], words[3],
             text.substr(eol + 1, next == std::string::npos ? std::string::npos : next - eol - 1), 0};
    file.addModule(std::move(m));
    at = next;
  }
  return file;
}

void SourceFile::addModule(Module m) {
  m.firstLine = static_cast<int>(lines.size()) + 1;
  splitLines(m.text, lines);
  text += "\n" + kModuleMark + m.key + kUnit + m.name + kUnit + m.importer + kUnit + m.written + "\n" + m.text;
  modules.push_back(std::move(m));
}

std::pair<std::string, int> SourceFile::locate(int line) const {
  for (auto m = modules.rbegin(); m != modules.rend(); ++m)
    if (line >= m->firstLine) return {m->name, line - m->firstLine + 1};
  return {name, line};
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
  const bool located = d.range.begin.line > 0;
  const auto [fileName, line] = file_ && located ? file_->locate(d.range.begin.line)
                                : std::pair<std::string, int>(file_ ? file_->name : "<input>", 0);
  out << fileName << ':';
  if (located) out << line << ':' << std::max(d.range.begin.col, 1) << ':';
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
