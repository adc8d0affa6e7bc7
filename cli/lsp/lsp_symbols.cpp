#include "cli/lsp/lsp_features.h"

namespace fgsg::cli::lsp {
namespace {

// LSP's SymbolKind.
constexpr int kSymbolField = 8, kSymbolFunction = 12, kSymbolConstant = 14, kSymbolProperty = 7;

bool contains(const frontend::SourceRange& outer, const frontend::SourceRange& inner) {
  auto before = [](const frontend::SourceLoc& x, const frontend::SourceLoc& y) {
    return x.line < y.line || (x.line == y.line && x.col <= y.col);
  };
  return before(outer.begin, inner.begin) && before(inner.end, outer.end);
}

}  // namespace

Json documentSymbols(const Analysis& a) {
  Json symbols = Json::array();
  for (const auto& d : a.definitions) {
    if (!d.inDocument) continue;
    int kind = kSymbolFunction;
    const char* detail = "rule";
    if (d.kind == Definition::Kind::Attr) kind = kSymbolProperty, detail = "attr";
    if (d.kind == Definition::Kind::Const) kind = kSymbolConstant, detail = "const";
    if (d.kind == Definition::Kind::Field) kind = kSymbolField, detail = "field";
    // LSP wants the name's range inside the declaration's.
    const frontend::SourceRange selection = contains(d.range, d.nameRange) ? d.nameRange : d.range;
    symbols.push_back(Json{{"name", d.name},
                           {"detail", detail},
                           {"kind", kind},
                           {"range", a.rangeOf(d.range)},
                           {"selectionRange", a.rangeOf(selection)}});
  }
  return symbols;
}

}  // namespace fgsg::cli::lsp
