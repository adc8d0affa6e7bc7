#include "cli/lsp/lsp_features.h"

#include "cli/lsp/lsp_builtin_help.h"
#include "cli/lsp/lsp_import_paths.h"
#include "cli/lsp/lsp_text.h"
#include "frontend/builtin_docs.h"
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
  // Each item added, or nullptr when it does not start like the name or is there already.
  auto add = [&](const std::string& label, int kind, const std::string& detail) -> Json* {
    if (!startsLike(label, prefix) || !seen.insert(label).second) return nullptr;
    items.push_back(Json{{"label", label},
                         {"kind", kind},
                         {"detail", detail},
                         {"textEdit", Json{{"range", replaced}, {"newText", label}}}});
    return &items.back();
  };
  // A builtin's markdown (lsp_builtin_help.h) shown beside its item; made for the items
  // offered only.
  auto document = [](Json* item, const auto& help) {
    if (!item) return;
    if (const std::string text = help(); !text.empty())
      (*item)["documentation"] = Json{{"kind", "markdown"}, {"value", text}};
  };
  // An object's members (scope.sx, geometry.area(), Scope.sx, F1.vector1 ...) once its '.' is written.
  const bool afterDot = prefix.find('.') != std::string::npos;
  for (const auto& d : a.definitions) {
    switch (d.kind) {
      case Definition::Kind::Rule: add(d.name, kItemClass, "rule"); break;
      case Definition::Kind::Attr: add(d.name, kItemProperty, "attr"); break;
      case Definition::Kind::Const: add(d.name, kItemConstant, "const"); break;
      case Definition::Kind::Field: add(d.name, kItemField, "field"); break;
    }
  }
  using frontend::BuiltinDocKind;
  // fgsg's commands and functions are not CGA's (split, extrude, rand, p ...): a .cga file
  // gets CityEngine's names the dialect knows (frontend/cga's tables).
  if (frontend::isCgaSource(a.path, text)) {
    for (const auto& op : frontend::cityEngineOperationNames())
      document(add(op, kItemFunction, "CityEngine operation"), [&] { return cgaBuiltinHelp(op); });
    for (const auto& function : frontend::cityEngineFunctionSignatures())
      document(add(function.first, kItemFunction, function.second), [&] { return cgaBuiltinHelp(function.first); });
    if (afterDot) {
      for (const auto& member : frontend::cityEngineGeometryFunctionNames()) {
        const std::string label = "geometry." + member;
        const auto* d = frontend::findBuiltinDoc(BuiltinDocKind::CgaFunction, label);
        document(add(label, kItemFunction, d ? d->signature : label + "()"), [&] { return cgaBuiltinHelp(label); });
      }
      for (const auto& d : frontend::builtinDocs())
        if (d.kind == BuiltinDocKind::CgaAttribute)
          document(add(d.name, kItemProperty, d.signature), [&] { return cgaBuiltinHelp(d.name); });
    }
  } else {
    for (const auto& c : frontend::allCommands())
      document(add(c.name, kItemFunction, c.signature), [&] { return fgsgBuiltinHelp(a, c.name); });
    for (const auto& f : frontend::allFunctions())
      document(add(f.name, kItemFunction, functionSignature(f)), [&] { return fgsgBuiltinHelp(a, f.name); });
    if (afterDot) {
      for (const auto& d : frontend::builtinDocs())
        if (d.kind == BuiltinDocKind::Query)
          document(add(d.name, kItemProperty, d.signature), [&] { return fgsgBuiltinHelp(a, d.name); });
      for (const auto& field : a.definitions)
        if (field.kind == Definition::Kind::Field)
          for (const auto& d : frontend::builtinDocs())
            if (d.kind == BuiltinDocKind::FieldMember) {
              const std::string label = field.name + "." + d.name;
              document(add(label, kItemProperty, "field query"), [&] { return fgsgBuiltinHelp(a, label); });
            }
    }
  }
  return Json{{"isIncomplete", false}, {"items", std::move(items)}};
}

}  // namespace fgsg::cli::lsp
