#include "runtime/io/file_extension.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace fgsg::rt::io {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace fgsg::rt::io
