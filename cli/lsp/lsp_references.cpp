#include "cli/lsp/lsp_features.h"

#include "cli/lsp/lsp_text.h"

#include <cctype>

namespace fgsg::cli::lsp {
namespace {

using frontend::SourceRange;

bool isWordByte(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The declarations the name under the cursor refers to, as definition() finds them.
std::vector<const Definition*> declarationsAt(const Analysis& a, const std::string& text, int line, int character) {
  const std::string lineText = lineAt(text, line);
  const size_t at = byteAtUtf16(lineText, character);
  auto found = a.find(nameAt(lineText, at, false));
  if (found.empty()) {
    const size_t dot = lineText.find('.', at);
    found = a.find(nameAt(lineText.substr(0, dot == std::string::npos ? lineText.size() : dot), at, false));
  }
  return found;
}

// Whole-word occurrences of `spelled` on lines [first, last] of the analysis' source, outside
// comments and strings; each range covers `spelled`'s last `tail` bytes (the name without
// its module's alias, which is what a rename changes). A name written after a '.' is
// another's member (Scope.sx), not this one, unless `spelled` is itself qualified.
void occurrences(const Analysis& a, int first, int last, const std::string& spelled, size_t tail,
                 std::vector<SourceRange>& out) {
  bool inBlockComment = false;
  for (int n = first; n <= last && n <= static_cast<int>(a.source.lines.size()); ++n) {
    const std::string& line = a.source.lines[n - 1];
    std::vector<int> colAt(line.size() + 1);  // each byte's column, in code points (1-based)
    for (size_t i = 0, col = 0; i <= line.size(); ++i) {
      if (i == line.size() || (static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) ++col;
      colAt[i] = static_cast<int>(col);
    }
    for (size_t i = 0; i < line.size();) {
      if (inBlockComment) {
        const size_t close = line.find("*/", i);
        if (close == std::string::npos) break;
        inBlockComment = false, i = close + 2;
      } else if (line.compare(i, 2, "//") == 0) {
        break;
      } else if (line.compare(i, 2, "/*") == 0) {
        inBlockComment = true, i += 2;
      } else if (line[i] == '"') {  // a string: up to its closing quote, escapes skipped
        for (++i; i < line.size() && line[i] != '"'; ++i)
          if (line[i] == '\\') ++i;
        ++i;
      } else if (line.compare(i, spelled.size(), spelled) == 0 &&
                 (i == 0 || (!isWordByte(line[i - 1]) && line[i - 1] != '.')) &&
                 (i + spelled.size() >= line.size() || !isWordByte(line[i + spelled.size()]))) {
        const size_t begin = i + spelled.size() - tail;  // names are ASCII: bytes are columns
        out.push_back(SourceRange{{n, colAt[begin]}, {n, colAt[begin] + static_cast<int>(tail) - 1}});
        i += spelled.size();
      } else {
        ++i;
      }
    }
  }
}

// Every place the declaration is named: in the document (qualified by its alias when it is
// a module's) and in the module that declares it.
std::vector<SourceRange> uses(const Analysis& a, const Definition& d) {
  const int documentLines = a.documentLines();
  const size_t dot = d.name.rfind('.');
  const std::string bare = dot == std::string::npos ? d.name : d.name.substr(dot + 1);
  std::vector<SourceRange> out;
  occurrences(a, 1, documentLines, d.name, bare.size(), out);
  if (!d.inDocument) {
    for (size_t m = 0; m < a.source.modules.size(); ++m) {
      const int firstLine = a.source.modules[m].firstLine;
      const int lastLine = m + 1 < a.source.modules.size() ? a.source.modules[m + 1].firstLine - 1
                                                           : static_cast<int>(a.source.lines.size());
      if (d.nameRange.begin.line >= firstLine && d.nameRange.begin.line <= lastLine)
        occurrences(a, firstLine, lastLine, bare, bare.size(), out);
    }
  }
  return out;
}

}  // namespace

Json references(const Analysis& a, const std::string& text, int line, int character, bool includeDeclaration) {
  Json locations = Json::array();
  const auto found = declarationsAt(a, text, line, character);
  if (found.empty()) return locations;
  for (const SourceRange& r : uses(a, *found.front())) {
    bool declaration = false;
    for (const Definition* d : found)
      declaration = declaration || (d->nameRange.begin.line == r.begin.line && d->nameRange.begin.col == r.begin.col);
    if (includeDeclaration || !declaration) locations.push_back(a.locationOf(r));
  }
  return locations;
}

Json rename(const Analysis& a, const std::string& text, int line, int character, const std::string& newName,
            std::string& error) {
  bool identifier = !newName.empty() && !std::isdigit(static_cast<unsigned char>(newName[0]));
  for (char c : newName) identifier = identifier && isWordByte(c);
  if (!identifier) {
    error = "'" + newName + "' is not a name (letters, digits and '_', not starting with a digit)";
    return nullptr;
  }
  const auto found = declarationsAt(a, text, line, character);
  if (found.empty()) {
    error = "no rule, attr, const or field of this grammar here to rename";
    return nullptr;
  }
  Json changes = Json::object();
  for (const SourceRange& r : uses(a, *found.front())) {
    const Json location = a.locationOf(r);
    const std::string uri = location["uri"];
    if (!changes.contains(uri)) changes[uri] = Json::array();
    changes[uri].push_back(Json{{"range", location["range"]}, {"newText", newName}});
  }
  return Json{{"changes", std::move(changes)}};
}

}  // namespace fgsg::cli::lsp
