#include "cli/lsp/lsp_features.h"
#include "cli/lsp/lsp_text.h"
#include "frontend/format_grammar.h"

#include <algorithm>

namespace fgsg::cli::lsp {

Json formatting(const std::string& path, const std::string& text, std::string& error) {
  const frontend::SourceFile file = frontend::SourceFile::make(path, text);
  frontend::Diagnostics diags(&file);
  std::string formatted;
  if (!frontend::formatGrammar(file, formatted, diags)) {
    const frontend::Diagnostic& first = diags.all().front();
    error = path + ":" + std::to_string(first.range.begin.line) + ":" + std::to_string(first.range.begin.col) +
            ": " + first.message + " (not formatted)";
    return nullptr;
  }
  if (formatted == text) return Json::array();
  // One edit over the whole text: its end is the last line's end, in UTF-16 units.
  const int lastLine = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  const std::string last = lineAt(text, lastLine);
  const int characters = static_cast<int>(std::count_if(
      last.begin(), last.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
  const Json end{{"line", lastLine}, {"character", utf16Units(last, characters)}};
  return Json::array({Json{{"range", Json{{"start", Json{{"line", 0}, {"character", 0}}}, {"end", end}}},
                           {"newText", formatted}}});
}

}  // namespace fgsg::cli::lsp
