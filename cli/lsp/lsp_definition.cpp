#include "cli/lsp/lsp_features.h"

#include "cli/lsp/lsp_text.h"

namespace fgsg::cli::lsp {

Json definition(const Analysis& a, const std::string& text, int line, int character) {
  const std::string lineText = lineAt(text, line);
  const size_t at = byteAtUtf16(lineText, character);
  std::string name = nameAt(lineText, at, false);
  // `alias.Name` is one name; `Scope.sx` is not declared: then the part up to the cursor's
  // segment (`facade` of `facade.Window` when the cursor is on `facade`).
  auto found = a.find(name);
  if (found.empty()) {
    const size_t dot = lineText.find('.', at);
    const std::string head = nameAt(lineText.substr(0, dot == std::string::npos ? lineText.size() : dot), at, false);
    if (head != name) found = a.find(head);
  }
  Json locations = Json::array();
  for (const Definition* d : found) locations.push_back(a.locationOf(d->nameRange));
  return locations;
}

}  // namespace fgsg::cli::lsp
