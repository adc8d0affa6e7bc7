// File helpers shared by the runtime tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace fgsg::test {

// An empty folder under the build tree: <build>/test-scratch/<group>/<pid>-<name>. Test
// cases run as parallel processes, and names made from a counter repeat across them.
inline std::filesystem::path scratchDir(const std::string& group, const std::string& name) {
  const auto dir = std::filesystem::path(FGSG_BINARY_DIR) / "test-scratch" / group /
                   (std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace fgsg::test
