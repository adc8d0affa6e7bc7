// File helpers shared by the runtime tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fgsg::test {

// An empty folder under the build tree, one per test case (cases may run as parallel
// processes): <build>/test-scratch/<group>/<name>.
inline std::filesystem::path scratchDir(const std::string& group, const std::string& name) {
  const auto dir = std::filesystem::path(FGSG_BINARY_DIR) / "test-scratch" / group / name;
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
