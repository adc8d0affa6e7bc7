#include "cli/lsp/lsp_import_paths.h"

#include "frontend/imports.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>

namespace fgsg::cli::lsp {

namespace fs = std::filesystem;

namespace {

// LSP's CompletionItemKind.
constexpr int kImportItemModule = 9, kImportItemFolder = 19;
// A folder of thousands of files (a home folder) lists no more than this.
constexpr size_t kMaxImportItems = 500;

// How an import names the grammar file `name`: ".fgsg" is what an import adds when the
// path has no extension, so it is left out; a .cga module keeps its extension.
std::optional<std::string> importNameOfFile(const fs::path& name) {
  if (name.extension() == ".fgsg") return name.stem().string();
  if (name.extension() == ".cga") return name.filename().string();
  return std::nullopt;
}

int importUtf16Length(const std::string& s) {
  int units = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if ((c & 0xC0) != 0x80) units += c >= 0xF0 ? 2 : 1;  // a lead byte; 4-byte: a surrogate pair
  }
  return units;
}

// The modules and folders in `dir`, named `written` + their name; label -> (kind, file).
void listImportFolder(const fs::path& dir, const std::string& written, const fs::path& self,
                      std::map<std::string, std::pair<int, std::string>>& found) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end && found.size() < kMaxImportItems; it.increment(ec)) {
    const fs::path& p = it->path();
    const std::string name = p.filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code statError;
    if (it->is_directory(statError)) {
      found.emplace(written + name + "/", std::make_pair(kImportItemFolder, p.string()));
    } else if (const auto imported = importNameOfFile(p); imported && it->is_regular_file(statError)) {
      if (!self.empty() && fs::equivalent(p, self, statError)) continue;  // importing itself is a cycle
      found.emplace(written + *imported, std::make_pair(kImportItemModule, p.string()));
    }
  }
}

// Every module of the standard library, as "std/folder/name", down to `depth` folders.
void listStandardModules(const fs::path& dir, const std::string& written, int depth,
                         std::map<std::string, std::pair<int, std::string>>& found) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end && found.size() < kMaxImportItems; it.increment(ec)) {
    const fs::path& p = it->path();
    std::error_code statError;
    if (it->is_directory(statError)) {
      if (depth > 0) listStandardModules(p, written + p.filename().string() + "/", depth - 1, found);
    } else if (const auto imported = importNameOfFile(p); imported && it->is_regular_file(statError)) {
      found.emplace(written + *imported, std::make_pair(kImportItemModule, p.string()));
    }
  }
}

}  // namespace

std::optional<std::string> importPathBeforeCursor(const std::string& beforeCursor) {
  static const std::regex fgsgImport(R"(^\s*import\s+"([^"]*)$)");
  static const std::regex cgaImport(R"(^\s*import\s+[A-Za-z_][A-Za-z_0-9]*\s*:\s*"([^"]*)$)");
  std::smatch m;
  if (std::regex_match(beforeCursor, m, fgsgImport) || std::regex_match(beforeCursor, m, cgaImport)) return m[1].str();
  return std::nullopt;
}

Json importPathItems(const std::string& documentPath, const std::string& typed, int line, int character) {
  const frontend::ImportSearch search = frontend::defaultImportSearch();
  std::map<std::string, std::pair<int, std::string>> found;
  const std::string typedFolder = typed.substr(0, typed.find_last_of('/') + 1);  // "" or "parts/"
  const bool standard = typed.rfind("std/", 0) == 0 || std::string("std/").rfind(typed, 0) == 0;
  if (typed.rfind("std/", 0) != 0) {
    // Beside the document (an untitled one has no folder: the working directory), then FGSG_PATH.
    const fs::path documentFolder = fs::path(documentPath).parent_path();
    listImportFolder((documentFolder.empty() ? fs::path(".") : documentFolder) / typedFolder, typedFolder,
                     documentPath, found);
    for (const std::string& dir : search.path) listImportFolder(fs::path(dir) / typedFolder, typedFolder, {}, found);
  }
  if (standard && !search.stdlib.empty()) listStandardModules(search.stdlib, "std/", 2, found);

  const int start = std::max(character - importUtf16Length(typed), 0);
  const Json range{{"start", {{"line", line}, {"character", start}}}, {"end", {{"line", line}, {"character", character}}}};
  Json items = Json::array();
  for (const auto& [label, what] : found) {
    if (label.compare(0, typed.size(), typed) != 0) continue;
    items.push_back(Json{{"label", label},
                         {"kind", what.first},
                         {"detail", what.second},
                         {"filterText", label},
                         {"textEdit", Json{{"range", range}, {"newText", label}}}});
  }
  return items;
}

}  // namespace fgsg::cli::lsp
