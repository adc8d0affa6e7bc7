#include "cli/lsp/lsp_builtin_help.h"

#include "frontend/builtin_docs.h"
#include "frontend/builtins.h"
#include "frontend/cga/cga_parse.h"

namespace fgsg::cli::lsp {
namespace {

using frontend::BuiltinDoc;
using frontend::BuiltinDocKind;
using frontend::findBuiltinDoc;

std::string builtinHelpMarkdown(const std::string& signature, const std::string& doc) {
  return "```\n" + signature + "\n```\n\n" + doc;
}

// An fgsg builtin by its name alone: a command, a function, a query, a surface or a field source.
const BuiltinDoc* fgsgBuiltinDocNamed(const std::string& name) {
  for (BuiltinDocKind kind : {BuiltinDocKind::Command, BuiltinDocKind::Function, BuiltinDocKind::Query,
                              BuiltinDocKind::Surface, BuiltinDocKind::FieldSource})
    if (const BuiltinDoc* d = findBuiltinDoc(kind, name)) return d;
  return nullptr;
}

}  // namespace

std::string fgsgBuiltinHelp(const Analysis& a, const std::string& name) {
  if (const BuiltinDoc* d = fgsgBuiltinDocNamed(name)) {
    std::string doc = d->doc;
    if (const auto* c = frontend::findCommand(name); c && c->laterIssue)
      doc += std::string("\n\n(its runtime comes with ") + c->laterIssue + ")";
    return builtinHelpMarkdown(frontend::builtinDocSignature(*d), doc);
  }
  // F1.vector1: a member of a field the grammar declares.
  const size_t dot = name.find('.');
  if (dot == std::string::npos) return "";
  const std::string field = name.substr(0, dot), member = name.substr(dot + 1);
  for (const Definition* d : a.find(field))
    if (d->kind == Definition::Kind::Field)
      if (const BuiltinDoc* m = findBuiltinDoc(BuiltinDocKind::FieldMember, member))
        return builtinHelpMarkdown(name, m->doc);
  return "";
}

std::string cgaBuiltinHelp(const std::string& name) {
  for (BuiltinDocKind kind :
       {BuiltinDocKind::CgaOperation, BuiltinDocKind::CgaFunction, BuiltinDocKind::CgaAttribute}) {
    const BuiltinDoc* d = findBuiltinDoc(kind, name);
    if (!d) continue;
    std::string help = builtinHelpMarkdown(d->signature, d->doc);
    if (const BuiltinDoc* target = d->fgsgName ? fgsgBuiltinDocNamed(d->fgsgName) : nullptr)
      help += "\n\nfgsg: `" + frontend::builtinDocSignature(*target) + "`: " + target->doc;
    return help;
  }
  // sin, cos ...: CityEngine's functions that fgsg has under the same name and meaning.
  for (const auto& [function, signature] : frontend::cityEngineFunctionSignatures())
    if (function == name)
      if (const BuiltinDoc* d = findBuiltinDoc(BuiltinDocKind::Function, name))
        return builtinHelpMarkdown(signature, d->doc);
  if (frontend::isCityEngineOperationName(name))
    return builtinHelpMarkdown(name + "(...)",
                               "A CityEngine operation fgsg does not translate yet (E800 where it is used).");
  return "";
}

}  // namespace fgsg::cli::lsp
