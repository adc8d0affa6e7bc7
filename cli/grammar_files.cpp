#include "cli/grammar_files.h"

#include "cli/options.h"

#include <filesystem>
#include <set>

namespace fgsg::cli {

namespace fs = std::filesystem;

std::vector<std::string> grammarDataFiles(const ir::Module& module, const std::string& grammarPath,
                                          const std::vector<std::string>& extra) {
  std::vector<std::string> names = extra;
  if (module.surface.present && !module.surface.path.empty()) names.push_back(module.surface.path);
  for (const ir::FieldSpec& f : module.fields)
    if (!f.path.empty()) names.push_back(f.path);
  for (const ir::EnvDecl& e : module.environment) names.push_back(e.detail);
  names.insert(names.end(), module.assets.begin(), module.assets.end());
  names.insert(names.end(), module.strings.begin(), module.strings.end());

  std::vector<std::string> dirs = grammarDataDirs(grammarPath);
  dirs.push_back(".");
  std::set<std::string> found;
  std::error_code ec;
  for (const std::string& name : names) {
    if (name.empty() || name.size() > 4096) continue;
    const fs::path p(name);
    for (const std::string& dir : dirs) {
      const fs::path candidate = p.is_absolute() ? p : fs::path(dir) / p;
      if (fs::is_regular_file(candidate, ec)) {
        found.insert(fs::absolute(candidate, ec).lexically_normal().string());
        break;
      }
      if (p.is_absolute()) break;
    }
  }
  return {found.begin(), found.end()};
}

}  // namespace fgsg::cli
