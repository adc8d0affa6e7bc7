#include "cli/lsp/lsp_features.h"

namespace fgsg::cli::lsp {
namespace {

int severityOf(frontend::Severity s) {
  switch (s) {
    case frontend::Severity::Error: return 1;
    case frontend::Severity::Warning: return 2;
    case frontend::Severity::Note: return 3;  // Information
  }
  return 1;
}

// The document's import that (directly or through other modules) read the module at
// `key`: the path string it writes, where a diagnostic inside that module is shown.
frontend::SourceRange importSiteOf(const Analysis& a, std::string key) {
  const frontend::SourceFile::Module* top = nullptr;
  for (size_t hops = 0; hops <= a.source.modules.size(); ++hops) {
    const frontend::SourceFile::Module* m = nullptr;
    for (const auto& candidate : a.source.modules)
      if (candidate.key == key) m = &candidate;
    if (!m) break;
    top = m;
    if (m->importer.empty()) break;
    key = m->importer;
  }
  if (top) {
    const std::string quoted = "\"" + top->written + "\"";
    for (int n = 1; n <= a.documentLines(); ++n) {
      const std::string& line = a.source.lines[n - 1];
      const size_t at = line.find(quoted);
      if (at == std::string::npos || line.find("import") == std::string::npos) continue;
      int col = 1;  // in code points, as the front end counts
      for (size_t i = 0; i < at; ++i)
        if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) ++col;
      return frontend::SourceRange{{n, col}, {n, col + static_cast<int>(quoted.size()) - 1}};
    }
  }
  return frontend::SourceRange{{1, 1}, {1, 1}};
}

}  // namespace

Json diagnosticsParams(const Analysis& a, const std::string& uri) {
  Json list = Json::array();
  for (const auto& d : a.diagnostics) {
    Json item{{"severity", severityOf(d.severity)}, {"source", "fgsg"}, {"message", d.message}};
    if (!d.code.empty()) item["code"] = d.code;
    if (d.range.begin.line <= 0) {
      item["range"] = a.rangeOf(frontend::SourceRange{{1, 1}, {1, 0}});
    } else if (const auto [file, line] = a.source.locate(d.range.begin.line); file == a.source.name) {
      item["range"] = a.rangeOf(d.range);
    } else {
      // In a module: its file:line:col as `fgsg check` prints it, on the import.
      std::string key;
      for (const auto& m : a.source.modules)
        if (d.range.begin.line >= m.firstLine) key = m.key;
      item["range"] = a.rangeOf(importSiteOf(a, key));
      item["message"] = "in " + file + ":" + std::to_string(line) + ":" + std::to_string(std::max(d.range.begin.col, 1)) +
                        ": " + d.message;
    }
    list.push_back(std::move(item));
  }
  return Json{{"uri", uri}, {"diagnostics", std::move(list)}};
}

}  // namespace fgsg::cli::lsp
