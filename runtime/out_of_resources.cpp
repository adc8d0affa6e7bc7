#include "runtime/out_of_resources.h"

#include "runtime/plugins/plugin_library.h"

#include <cerrno>
#include <cstring>
#include <new>
#include <stdexcept>
#include <system_error>

namespace fgsg::rt {

std::string outOfResources(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "no memory left";
  if (const auto* s = dynamic_cast<const std::system_error*>(&e)) {
    const std::error_code c = s->code();
    if (c == std::errc::not_enough_memory || c == std::errc::resource_unavailable_try_again)
      return std::string("cannot start a thread: ") + s->what();
    return "";
  }
  if (const auto* p = dynamic_cast<const PluginError*>(&e); p && p->outOfMemory)
    return std::string("cannot load a part of fgsg: ") + e.what();
  static constexpr const char kTbbThread[] = "pthread_create has failed";
  if (dynamic_cast<const std::runtime_error*>(&e) && std::strncmp(e.what(), kTbbThread, sizeof kTbbThread - 1) == 0)
    return std::string("cannot start a worker thread: ") + e.what();
  return "";
}

}  // namespace fgsg::rt
