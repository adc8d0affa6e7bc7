// The session's statements as one text: assembled to be compiled (with where each
// statement landed, so that diagnostics are mapped back to the input or file it came
// from), and written out for :save.
#include "cli/repl_session.h"
#include "cli/repl_statements.h"
#include "ir/pipeline.h"

#include <algorithm>
#include <ostream>
#include <string>

namespace fgsg::cli::repl {

using frontend::SourceFile;
using frontend::SourceLoc;

Assembled Session::assemble(const std::vector<Statement>& list, bool valuesOnly) const {
  std::string text;
  Assembled a;
  int line = 1;
  int priority = 0;
  for (const Statement& s : list) {
    const bool isRule = s.key.rfind("rule:", 0) == 0;
    if (valuesOnly && s.key.rfind("value:", 0) != 0 && s.key.rfind("import:", 0) != 0) continue;  // modules' values too
    if (isRule && s.priority != priority) {
      text += "priority " + std::to_string(s.priority) + ":\n";
      ++line;
      priority = s.priority;
    }
    Segment seg;
    seg.firstLine = line;
    seg.lineCount = 1 + static_cast<int>(std::count(s.text.begin(), s.text.end(), '\n'));
    seg.origin = s.origin;
    seg.originLine = s.line;
    seg.colShift = 0;
    a.segments.push_back(seg);
    text += std::string(static_cast<size_t>(std::max(0, s.col - 1)), ' ') + s.text + ";\n";
    line += seg.lineCount;
  }
  // Declarations alone are not a grammar yet (E024): a placeholder start keeps them
  // compilable, outside every segment, so it never shows in a diagnostic.
  if (!valuesOnly && !hasStart(list)) text += "ReplEmpty__ ~> epsilon;\n";
  a.source = SourceFile::make("<session>", text);
  return a;
}

std::string Session::grammarText() const {
  std::string text = "// written by fgsg repl\n";
  int priority = 0;
  for (const Statement& s : statements_) {
    if (s.key.rfind("rule:", 0) == 0 && s.priority != priority) {
      text += "priority " + std::to_string(s.priority) + ":\n";
      priority = s.priority;
    }
    text += s.text + ";\n";
  }
  return text;
}

void Session::printMapped(const Assembled& a, const frontend::Diagnostic& d,
                          std::ostream& err) const {
  frontend::Diagnostic mapped = d;
  const SourceFile* file = &a.source;
  for (const Segment& s : a.segments) {
    const int l = d.range.begin.line;
    if (l >= s.firstLine && l < s.firstLine + s.lineCount) {
      auto shift = [&](SourceLoc& loc) {
        if (loc.line == s.firstLine) loc.col = std::max(1, loc.col - s.colShift);
        loc.line = loc.line - s.firstLine + s.originLine;
      };
      shift(mapped.range.begin);
      if (d.range.end.line >= s.firstLine && d.range.end.line < s.firstLine + s.lineCount)
        shift(mapped.range.end);
      else
        mapped.range.end = mapped.range.begin;
      file = s.origin.get();
      break;
    }
  }
  frontend::Diagnostics one(file);
  err << one.format(mapped) << "\n";
}

bool Session::compile(const Assembled& a, ir::Module& out, std::ostream& err,
                      const SourceFile* warningsFor) const {
  SourceFile source = a.source;  // gains the texts of the modules it imports
  frontend::Diagnostics diags(&source);
  const bool ok = ir::compileSource(source, out, diags);
  for (const auto& d : diags.all()) {
    if (d.severity != frontend::Severity::Error) {
      // Warnings of earlier inputs were shown when they were typed.
      bool mine = false;
      for (const Segment& s : a.segments)
        if (d.range.begin.line >= s.firstLine && d.range.begin.line < s.firstLine + s.lineCount)
          mine = s.origin.get() == warningsFor;
      if (!mine || !warningsFor) continue;
    }
    printMapped(a, d, err);
  }
  return ok;
}

}  // namespace fgsg::cli::repl
