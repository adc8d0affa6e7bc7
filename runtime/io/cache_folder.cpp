#include "runtime/io/cache_folder.h"

#include <cstdlib>

namespace fgsg::rt::io {

std::string cacheFolder() {
  if (const char* dir = std::getenv("FGSG_CACHE_DIR")) {
    const std::string d = dir;
    return d == "off" ? std::string() : d;
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/fgsg";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/fgsg";
  return {};
}

}  // namespace fgsg::rt::io
