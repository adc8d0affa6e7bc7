#include "runtime/io/find_file.h"

#include <filesystem>
#include <system_error>

namespace fgsg::rt::io {

std::string findFile(const std::string& name, const std::vector<std::string>& dirs) {
  namespace fs = std::filesystem;
  for (const auto& dir : dirs) {
    std::error_code ec;
    if (fs::is_regular_file(fs::path(dir) / name, ec)) return (fs::path(dir) / name).string();
  }
  return name;
}

}  // namespace fgsg::rt::io
