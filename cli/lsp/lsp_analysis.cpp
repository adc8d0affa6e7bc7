#include "cli/lsp/lsp_analysis.h"

#include "cli/check_data_files.h"
#include "cli/lsp/lsp_text.h"
#include "ir/pipeline_reusing.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <tuple>

namespace fgsg::cli::lsp {
namespace {

using frontend::SourceLoc;
using frontend::SourceRange;

bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

// A range that ends where it starts when the front end did not record its end.
SourceRange ordered(SourceRange r) {
  if (r.end.line < r.begin.line || (r.end.line == r.begin.line && r.end.col < r.begin.col)) r.end = r.begin;
  return r;
}

// Where `name` is written on `line` at or after code point `fromCol` (1-based), as a
// whole word: its range, or line 0 when it is not there.
SourceRange writtenAt(const std::string& line, int lineNumber, int fromCol, const std::string& name) {
  std::vector<size_t> starts;  // the byte each code point starts at
  for (size_t i = 0; i < line.size(); ++i)
    if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) starts.push_back(i);
  auto isWordByte = [&](size_t i) { return std::isalnum(static_cast<unsigned char>(line[i])) || line[i] == '_'; };
  for (size_t c = std::max(fromCol, 1) - 1; c < starts.size(); ++c) {
    const size_t at = starts[c];
    if (line.compare(at, name.size(), name) != 0) continue;
    if ((at > 0 && isWordByte(at - 1)) || (at + name.size() < line.size() && isWordByte(at + name.size()))) continue;
    const int col = static_cast<int>(c) + 1;
    return SourceRange{{lineNumber, col}, {lineNumber, col + static_cast<int>(name.size()) - 1}};
  }
  return SourceRange{};
}

void collectDefinitions(Analysis& a) {
  const int documentLines = a.documentLines();
  std::set<std::tuple<std::string, int, int>> seen;
  auto add = [&](Definition::Kind kind, const std::string& name, const SourceRange& range, const SourceLoc& from) {
    const std::string shown = frontend::symbolDisplayName(name);
    // A .cga rule's helpers (`Roof$1`) are the translator's, not the user's.
    if (shown.empty() || shown.find('$') != std::string::npos || range.begin.line <= 0 || from.line <= 0 ||
        from.line > static_cast<int>(a.source.lines.size()))
      return;
    // The name as written where it is declared (a module's without its alias): a rule the
    // .cga translator made up (its start rules, a case's branches) is not written there.
    const size_t dot = shown.rfind('.');
    const std::string written = dot == std::string::npos ? shown : shown.substr(dot + 1);
    const SourceRange nameRange = writtenAt(a.source.lines[from.line - 1], from.line, from.col, written);
    if (nameRange.begin.line == 0) return;
    // Once per name and place (a .cga rule's translation repeats its head); a set, not a
    // search of the list, which was quadratic: 2 000 rules took 3 % of a change.
    if (!seen.insert({shown, nameRange.begin.line, nameRange.begin.col}).second) return;
    a.definitions.push_back({kind, shown, ordered(range), nameRange, range.begin.line <= documentLines});
  };
  for (const auto& rule : a.program.rules)
    add(Definition::Kind::Rule, rule.predecessor.name, rule.range, rule.predecessor.range.begin);
  for (const auto& value : a.program.values)
    add(value.isAttr ? Definition::Kind::Attr : Definition::Kind::Const, value.name, value.range, value.range.begin);
  for (const auto& field : a.program.fields)
    add(Definition::Kind::Field, field.name, field.range, field.nameRange.begin.line > 0 ? field.nameRange.begin : field.range.begin);
  // The document's in the order written, then the modules'.
  std::stable_sort(a.definitions.begin(), a.definitions.end(), [](const Definition& x, const Definition& y) {
    if (x.inDocument != y.inDocument) return x.inDocument;
    return x.range.begin.line != y.range.begin.line ? x.range.begin.line < y.range.begin.line
                                                    : x.range.begin.col < y.range.begin.col;
  });
}

}  // namespace

int Analysis::documentLines() const {
  return source.modules.empty() ? static_cast<int>(source.lines.size()) : source.modules.front().firstLine - 1;
}

Analysis::Place Analysis::placeOf(int wholeLine) const {
  for (auto m = source.modules.rbegin(); m != source.modules.rend(); ++m)
    if (wholeLine >= m->firstLine) return {m->key, wholeLine - m->firstLine, false};
  return {path, std::max(wholeLine - 1, 0), true};
}

Json Analysis::rangeOf(const SourceRange& given) const {
  const SourceRange r = ordered(given);
  auto position = [&](int line, int col) {
    if (line <= 0) return Json{{"line", 0}, {"character", 0}};
    const std::string text = line <= static_cast<int>(source.lines.size()) ? source.lines[line - 1] : "";
    return Json{{"line", placeOf(line).line}, {"character", utf16Units(text, std::max(col, 1) - 1)}};
  };
  // The front end's end is the last character, inclusive: LSP's is the one after it.
  return Json{{"start", position(r.begin.line, r.begin.col)}, {"end", position(r.end.line, r.end.col + 1)}};
}

Json Analysis::locationOf(const SourceRange& range) const {
  return Json{{"uri", uriOfPath(placeOf(range.begin.line).path)}, {"range", rangeOf(range)}};
}

std::vector<const Definition*> Analysis::find(const std::string& name) const {
  std::vector<const Definition*> out;
  for (const auto& d : definitions)
    if (d.name == name) out.push_back(&d);
  return out;
}

std::shared_ptr<Analysis> analyze(const std::string& path, const std::string& text,
                                  std::shared_ptr<Analysis> previous) {
  auto a = std::make_shared<Analysis>();
  a->path = path;
  // What `fgsg check` reports (cli/cmd_check.cpp): the compile's diagnostics, then, when it
  // compiled, the data files' (fields, meshes, images the grammar names). The compile keeps
  // the parsed program, with what could be built of it after errors.
  a->source = frontend::SourceFile::make(path, text);
  frontend::Diagnostics diags(&a->source);
  ir::Module module;
  frontend::StatementReuse reuse;
  if (previous && previous.use_count() == 1 && previous->path == path) {
    reuse.offer(previous->program, std::move(previous->statements));
    reuse.offerTokens(std::move(previous->tokens));
  }
  if (ir::compileSourceReusing(a->source, module, diags, a->program, reuse)) checkDataFiles(module, path, diags);
  a->statements = reuse.takeRecorded();
  a->tokens = reuse.takeTokens();
  a->diagnostics = diags.all();
  collectDefinitions(*a);
  return a;
}

std::string nameAt(const std::string& line, size_t at, bool prefixOnly) {
  at = std::min(at, line.size());
  size_t begin = at, end = at;
  while (begin > 0 && isNameChar(line[begin - 1])) --begin;
  if (!prefixOnly)
    while (end < line.size() && isNameChar(line[end])) ++end;
  std::string name = line.substr(begin, end - begin);
  while (!name.empty() && name.front() == '.') name.erase(0, 1);
  while (!name.empty() && name.back() == '.') name.pop_back();
  return prefixOnly && at > begin && line[at - 1] == '.' ? name + "." : name;
}

}  // namespace fgsg::cli::lsp
