#include "cli/lsp/lsp_features.h"

#include "cli/lsp/lsp_text.h"
#include "frontend/builtins.h"

namespace fgsg::cli::lsp {
namespace {

Json markdownCode(const std::string& code, const std::string& after) {
  return Json{{"contents", Json{{"kind", "markdown"}, {"value", "```\n" + code + "\n```" + after}}}};
}

}  // namespace

Json hover(const Analysis& a, const std::string& text, int line, int character) {
  const std::string lineText = lineAt(text, line);
  const std::string name = nameAt(lineText, byteAtUtf16(lineText, character), false);
  if (name.empty()) return nullptr;
  // The grammar's own names first: a rule may share a builtin's name in a .cga file.
  if (const auto found = a.find(name); !found.empty()) {
    const Definition& d = *found.front();
    const int wholeLine = d.range.begin.line;
    std::string declared = wholeLine <= static_cast<int>(a.source.lines.size()) ? a.source.lines[wholeLine - 1] : name;
    declared.erase(0, declared.find_first_not_of(" \t"));
    const Analysis::Place place = a.placeOf(wholeLine);
    return markdownCode(declared, place.inDocument ? "" : "\n\n" + place.path + ":" + std::to_string(place.line + 1));
  }
  if (const auto* c = frontend::findCommand(name))
    return markdownCode(c->signature, c->laterIssue ? std::string("\n\n(its runtime comes with ") + c->laterIssue + ")" : "");
  if (const auto* f = frontend::findFunction(name)) {
    std::string args;
    for (int i = 0; i < f->maxArgs; ++i) args += (i ? ", " : "") + std::string(1, static_cast<char>('a' + i));
    return markdownCode(std::string(f->name) + "(" + args + ")", "");
  }
  return nullptr;
}

}  // namespace fgsg::cli::lsp
