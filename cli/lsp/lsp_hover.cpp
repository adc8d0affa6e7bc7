#include "cli/lsp/lsp_features.h"

#include "cli/lsp/lsp_builtin_help.h"
#include "cli/lsp/lsp_text.h"
#include "frontend/cga/cga_parse.h"

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
  // A builtin: its signature and its doc from frontend/builtin_docs.cpp's table.
  const std::string help = frontend::isCgaSource(a.path, text) ? cgaBuiltinHelp(name) : fgsgBuiltinHelp(a, name);
  if (help.empty()) return nullptr;
  return Json{{"contents", Json{{"kind", "markdown"}, {"value", help}}}};
}

}  // namespace fgsg::cli::lsp
