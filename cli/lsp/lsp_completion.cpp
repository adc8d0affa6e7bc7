#include "cli/lsp/lsp_features.h"

#include "cli/lsp/lsp_import_paths.h"
#include "cli/lsp/lsp_text.h"
#include "frontend/builtins.h"
#include "frontend/cga/cga_parse.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace fgsg::cli::lsp {
namespace {

// LSP's CompletionItemKind.
constexpr int kItemFunction = 3, kItemField = 5, kItemClass = 7, kItemProperty = 10, kItemConstant = 21;

bool startsLike(const std::string& name, const std::string& prefix) {
  if (prefix.size() > name.size()) return false;
  for (size_t i = 0; i < prefix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(name[i])) != std::tolower(static_cast<unsigned char>(prefix[i])))
      return false;
  return true;
}

std::string functionSignature(const frontend::FunctionInfo& f) {
  std::string s = std::string(f.name) + "(";
  for (int i = 0; i < f.maxArgs; ++i) s += (i ? ", " : "") + std::string(1, static_cast<char>('a' + i));
  return s + ")";
}

}  // namespace

Json completion(const Analysis& a, const std::string& text, int line, int character) {
  const std::string lineText = lineAt(text, line);
  const size_t cursor = byteAtUtf16(lineText, character);
  // Inside an import's path: the modules it may name, and nothing else.
  if (const auto typed = importPathBeforeCursor(lineText.substr(0, cursor)))
    return Json{{"isIncomplete", false}, {"items", importPathItems(a.path, *typed, line, character)}};
  const std::string prefix = nameAt(lineText, cursor, true);
  Json items = Json::array();
  // '"' and '/' trigger completion for import paths; elsewhere (a string, a division) they
  // start no name.
  if (prefix.empty() && cursor > 0 && (lineText[cursor - 1] == '"' || lineText[cursor - 1] == '/'))
    return Json{{"isIncomplete", false}, {"items", std::move(items)}};
  std::set<std::string> seen;
  // Each item replaces the whole name being written, its alias included: an editor's own
  // idea of a word stops at the '.', and would write `parts.parts.Window`.
  const Json replaced{{"start", {{"line", line}, {"character", std::max(character - static_cast<int>(prefix.size()), 0)}}},
                      {"end", {{"line", line}, {"character", character}}}};
  auto add = [&](const std::string& label, int kind, const std::string& detail) {
    if (!startsLike(label, prefix) || !seen.insert(label).second) return;
    items.push_back(Json{{"label", label},
                         {"kind", kind},
                         {"detail", detail},
                         {"textEdit", Json{{"range", replaced}, {"newText", label}}}});
  };
  for (const auto& d : a.definitions) {
    switch (d.kind) {
      case Definition::Kind::Rule: add(d.name, kItemClass, "rule"); break;
      case Definition::Kind::Attr: add(d.name, kItemProperty, "attr"); break;
      case Definition::Kind::Const: add(d.name, kItemConstant, "const"); break;
      case Definition::Kind::Field: add(d.name, kItemField, "field"); break;
    }
  }
  // fgsg's commands and functions are not CGA's (split, extrude, rand, p ...): a .cga file
  // gets CityEngine's names the dialect knows (frontend/cga's tables).
  if (frontend::isCgaSource(a.path, text)) {
    for (const auto& op : frontend::cityEngineOperationNames()) add(op, kItemFunction, "CityEngine operation");
    for (const auto& [name, signature] : frontend::cityEngineFunctionSignatures()) add(name, kItemFunction, signature);
  } else {
    for (const auto& c : frontend::allCommands()) add(c.name, kItemFunction, c.signature);
    for (const auto& f : frontend::allFunctions()) add(f.name, kItemFunction, functionSignature(f));
  }
  return Json{{"isIncomplete", false}, {"items", std::move(items)}};
}

}  // namespace fgsg::cli::lsp
