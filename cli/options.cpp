#include "cli/options.h"

#include <cctype>
#include <filesystem>

namespace fgsg::cli {

std::vector<std::string> grammarDataDirs(const std::string& grammarFile) {
  const auto dir = std::filesystem::path(grammarFile).parent_path();
  return {(dir.empty() ? std::filesystem::path(".") : dir).string(), (dir / "assets").string()};
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace fgsg::cli
